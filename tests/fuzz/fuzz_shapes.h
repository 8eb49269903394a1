/* Shape fuzzing, world-free: raw bytes -> two geometries of any type
   (circles, capsules, polygons with a radius, segments, chain segments
   with ghosts, and types out of range), made by the library's makers or
   filled by hand (inconsistent normals, a wrong count, CW or non-convex
   outlines, coincident ends, huge, tiny, NaN), two transforms (unit
   rotors, rotors off unit by about the collider's 1e-4 tolerance, wild
   ones) and a length unit -> ga2d_collide_shapes_scaled in both argument
   orders; then the mass functions on each geometry and the polygon
   makers.

   What is checked (the header's promises):
     collide   a refusal is a negative -GA2D_ERR_* that the input earns
               (NOT_FINITE for a non-finite value it reads, INVALID_ARGUMENT
               for a bad type or count, a negative radius, a polygon whose
               normals are not unit or not out of their edges, a rotor off
               unit by more than 1e-4, a unit <= 0; either, where a value
               sits within rounding of a tolerance) with *out untouched;
               an answer is count 0..2 (at most 1 with a circle or a point),
               m.count = the return, a unit normal (within the rotors' and
               the polygons' own tolerance), finite points, anchors and
               separations (for sizes well inside the real range), no point
               farther apart than the speculative distance, and the anchors
               the point relative to each origin;
     oracle    for convex shapes (checked here, in double) the separations
               are bounded below by the cores' own geometry: a contact point
               lies on B's core within A's face slab, so its separation is
               at least the SAT value (less the reference choice's 0.1 slop)
               and, once the cores are surely apart, their true distance;
               a circle or point against anything convex has its one point
               at the signed distance along the true direction;
     symmetry  swapping A and B: the same refusal; a chain segment's
               manifold mirrored bit for bit (the collider computes it in
               the chain's frame either way: the normal negated, the points
               equal, the anchors swapped, the flip bit of each id toggled);
               otherwise counts where well defined (a point pair away from
               the margin) and never "none" in one order with a point well
               inside the margin in the other; normals opposite for point
               pairs that are apart;
     chains    a chain segment's contact is the plain segment's manifold (the
               same hull in the same frame) with a normal to its left; two
               chain segments never collide;
     mass      circle, capsule, polygon (radius included): the documented
               refusals (INVALID_ARGUMENT for NULL or a negative radius or
               density, NOT_FINITE, TOO_LARGE only where a term overflows),
               *out untouched and the unchecked form all zero on refusal,
               and when OK the same as the unchecked form, finite, mass
               matching an independent formula, inertia >= 0;
     makers    the _checked forms of the rounded box and the regular polygon
               give the unchecked forms bit for bit (count 0 on failure),
               refuse with their documented codes, and make what they say
               (the outline spanning 2 hw x 2 hh, vertex 0 on +x at r).

   Tolerances: eps = the build's machine epsilon; S = the size of the pair
   (the 1-norm of the offset between the origins plus each shape's reach,
   its radius included); delta = (256 eps + 4 (rotor and normal deviations
   from unit)) S: what two frames' roundings and two slightly non-unit
   rotors can move a point by.  Each bound is derived where it is used.

   Findings, each fixed and its input kept in tests/fuzz/regress/shapes/:
   a round point a subnormal distance away (a NaN normal); two segments
   whose incident one stands nearly perpendicular on the other's end
   (clipped to nothing in one order); a polygon smaller than the rounding
   of its placement in the other's frame (its vertices collapse there,
   its normals stay: measured against a circle along a face that had lost
   its direction); a huge circle's centre 1e75 off a box, past a side's end
   at 1.4 degrees (the side's placed edge, its ends rounded to one x, put
   the foot on the face: -3e71 in one order, nothing in the other). */
#ifndef GA2D_FUZZ_SHAPES_H
#define GA2D_FUZZ_SHAPES_H

#include "fuzz_common.h"

#define FG_MAXV GA2D_MAX_POLYGON_VERTICES
#define FG_UNIT_TOL 1e-4 /* the collider's |q|^2 and |n|^2 tolerance, and its perpendicularity one */
#define FG_SLOP ((double)GA2D_LINEAR_SLOP)
/* GJK's answers in the two argument orders, warm or cold, agree to the
   rounding and its progress test, and, for shapes under 1e-13 m in float
   (its simplex's dot products near 1e-30), to this: a billionth of the
   slop, beneath any length the library acts on */
#define FG_GJK_FLOOR (1e-9 * FG_SLOP)

#ifdef GA2D_DOUBLE
#define FG_NEXT(x) nextafter((x), 1e300)
#else
#define FG_NEXT(x) nextafterf((x), 1e30f)
#endif

#ifdef FUZZ_VERBOSE
#define FG_TRACE(args) (fprintf args)
#else
#define FG_TRACE(args) ((void)0)
#endif

/* What the harness knows of a geometry it made, worked out without the
   library: the collider's answer is predicted from it. */
typedef struct fg_info {
    int nf;        /* a value the collider reads is not finite */
    int inv;       /* a bad type or count, a negative radius, an inconsistent polygon */
    int maybe;     /* within rounding of one of the polygon check's tolerances */
    int oracle;    /* a convex core with exact normals: the distance oracle applies */
    int point;     /* a circle, or two ends that coincide: one contact point at most */
    int chain;     /* a chain segment */
    double reach;  /* the farthest its surface gets from its origin (1-norm) */
    double radius; /* its round part */
    double ndev;   /* the most a polygon normal's |n|^2 is off 1 */
    double extent; /* its core's size: a polygon's larger side, a segment's length */
} fg_info;

/* ------------------------------------------------------------- doubles */
typedef struct fg_d2 { double x, y; } fg_d2;
static fg_d2 fg_d2_make(double x, double y)
{
    fg_d2 d;
    d.x = x;
    d.y = y;
    return d;
}
static fg_d2 fg_d(ga2d_vec v) { return fg_d2_make((double)v.x, (double)v.y); }
static fg_d2 fg_sub(fg_d2 a, fg_d2 b) { return fg_d2_make(a.x - b.x, a.y - b.y); }
static fg_d2 fg_add(fg_d2 a, fg_d2 b) { return fg_d2_make(a.x + b.x, a.y + b.y); }
static fg_d2 fg_scale(fg_d2 a, double s) { return fg_d2_make(a.x * s, a.y * s); }
static double fg_dot(fg_d2 a, fg_d2 b) { return a.x * b.x + a.y * b.y; }
static double fg_cross(fg_d2 a, fg_d2 b) { return a.x * b.y - a.y * b.x; }
static double fg_len(fg_d2 a) { return hypot(a.x, a.y); }
static double fg_norm1(ga2d_vec v) { return fabs((double)v.x) + fabs((double)v.y); }

/* ------------------------------------------------------ classification */
/* The collider's polygon check (ga2d_collide_polygons' comment: zero
   edges, normals not unit or not out of their edges), mirrored in double
   on the edges as the library forms them (ga2d_real differences), with a
   margin of rounding around each tolerance where either answer is right:
   its dot products round by a few eps of |n| |e|, and a product that
   underflows by the smallest subnormal. */
static void fg_classify_polygon(const ga2d_polygon *p, fg_info *in)
{
    int i, j, n = p->count;
    double L = 0, lox, hix, loy, hiy, tilt = 0;
    if (n < 3 || n > FG_MAXV) {
        in->inv = 1;
        return;
    }
    for (i = 0; i < n; ++i)
        if (!fz_finite_vec(p->vertices[i]) || !fz_finite_vec(p->normals[i])) in->nf = 1;
    if (!fz_finite((double)p->radius)) in->nf = 1;
    if (p->radius < 0) in->inv = 1;
    if (in->nf) return; /* nothing else is looked at: NOT_FINITE whatever */
    lox = hix = (double)p->vertices[0].x;
    loy = hiy = (double)p->vertices[0].y;
    for (i = 0; i < n; ++i) {
        ga2d_vec er = ga2d_vec_sub(p->vertices[(i + 1) % n], p->vertices[i]);
        fg_d2 e = fg_d(er), nr = fg_d(p->normals[i]);
        double len = fg_len(e), nn = fg_dot(nr, nr), dev = fabs(nn - 1), w, perp;
        double tol = 8 * FZ_EPS * fg_len(nr) * len + 4 * FZ_TINY;
        lox = fmin(lox, (double)p->vertices[i].x);
        hix = fmax(hix, (double)p->vertices[i].x);
        loy = fmin(loy, (double)p->vertices[i].y);
        hiy = fmax(hiy, (double)p->vertices[i].y);
        in->ndev = fmax(in->ndev, dev);
        if (!fz_finite_vec(er) || len > FZ_REAL_MAX / 2) {
            in->maybe = 1; /* the edge overflows: the library's own verdict */
            continue;
        }
        if (len == 0) {
            in->inv = 1;
            continue;
        }
        if (fabs(dev - FG_UNIT_TOL) <= 8 * FZ_EPS) in->maybe = 1;
        else if (dev > FG_UNIT_TOL) in->inv = 1;
        w = fg_cross(nr, e);
        if (fabs(w) <= tol) in->maybe = 1;
        else if (w < 0) in->inv = 1;
        perp = fabs(fg_dot(nr, e));
        if (fabs(perp - FG_UNIT_TOL * len) <= tol + 4 * FZ_EPS * FG_UNIT_TOL * len) in->maybe = 1;
        else if (perp > FG_UNIT_TOL * len) in->inv = 1;
        /* how far the normal is from the edge's own */
        if (len > 0) tilt = fmax(tilt, fg_len(fg_sub(nr, fg_d2_make(e.y / len, -e.x / len))));
    }
    L = fmax(hix - lox, hiy - loy);
    in->extent = L;
    in->radius = (double)p->radius;
    for (i = 0; i < n; ++i) in->reach = fmax(in->reach, fg_norm1(p->vertices[i]));
    in->reach += in->radius;
    if (in->inv || in->maybe || !(L > 0)) return;
    /* the oracle wants a strictly convex CCW core (every other vertex left
       of each edge) with normals as exact as a maker's (within 64 eps) */
    if (tilt > 64 * FZ_EPS) return;
    for (i = 0; i < n; ++i) {
        fg_d2 a = fg_d(p->vertices[i]), e = fg_sub(fg_d(p->vertices[(i + 1) % n]), a);
        for (j = 0; j < n; ++j) {
            if (j == i || j == (i + 1) % n) continue;
            if (!(fg_cross(e, fg_sub(fg_d(p->vertices[j]), a)) > 1e-6 * L * fg_len(e))) return;
        }
    }
    in->oracle = 1;
}

/* Two ends of a capsule or segment: coincident ends are a point; ends
   apart by less than 1e-4 of the reach may become one in the other frame,
   and are kept out of the oracle. */
static void fg_classify_ends(ga2d_vec p1, ga2d_vec p2, double radius, fg_info *in)
{
    double e;
    if (!fz_finite_vec(p1) || !fz_finite_vec(p2) || !fz_finite(radius)) {
        in->nf = 1;
        return;
    }
    if (radius < 0) in->inv = 1;
    in->radius = radius;
    in->reach = fmax(fg_norm1(p1), fg_norm1(p2)) + radius;
    in->point = p1.x == p2.x && p1.y == p2.y;
    e = fg_len(fg_sub(fg_d(p2), fg_d(p1)));
    in->extent = e;
    if (!in->inv && (in->point || e >= 1e-4 * in->reach) && fz_finite_vec(ga2d_vec_sub(p2, p1))) in->oracle = 1;
}

static void fg_classify(const ga2d_geometry *g, fg_info *in)
{
    memset(in, 0, sizeof *in);
    switch ((int)g->type) {
    case GA2D_SHAPE_CIRCLE:
        fg_classify_ends(g->as.circle.center, g->as.circle.center, (double)g->as.circle.radius, in);
        in->point = 1;
        break;
    case GA2D_SHAPE_CAPSULE:
        fg_classify_ends(g->as.capsule.center1, g->as.capsule.center2, (double)g->as.capsule.radius, in);
        break;
    case GA2D_SHAPE_POLYGON: fg_classify_polygon(&g->as.polygon, in); break;
    case GA2D_SHAPE_SEGMENT: fg_classify_ends(g->as.segment.point1, g->as.segment.point2, 0, in); break;
    case GA2D_SHAPE_CHAIN_SEGMENT: {
        const ga2d_chain_segment *c = &g->as.chain_segment;
        fg_classify_ends(c->segment.point1, c->segment.point2, 0, in);
        if (!fz_finite_vec(c->ghost1) || !fz_finite_vec(c->ghost2)) in->nf = 1;
        in->chain = 1;
        in->oracle = 0; /* one-sided, with ghosts: checked against the plain segment instead */
        break;
    }
    default: in->inv = 1; break;
    }
    if (in->nf || in->inv) in->oracle = 0;
}

/* -------------------------------------------------------------- making */
static ga2d_real fg_coord(fz_reader *r, int wild)
{
    return wild ? fz_real(r, 2) : fz_narrow((double)(int8_t)fz_u8(r) / 32);
}
static ga2d_vec fg_vec(fz_reader *r, int wild)
{
    ga2d_vec v;
    v.x = fg_coord(r, wild);
    v.y = fg_coord(r, wild);
    return v;
}
/* an ordinary size in (0, 4], or anything */
static ga2d_real fg_size(fz_reader *r, int wild)
{
    return wild ? fz_real_pos(r, 2) : fz_narrow((double)(1 + fz_u8(r)) / 64);
}
/* a radius: mostly 0 or up to 1, sometimes anything */
static ga2d_real fg_radius(fz_reader *r)
{
    unsigned k = fz_u8(r);
    if (k < 64) return 0;
    if (k < 224) return fz_narrow((double)fz_u8(r) / 256);
    return fz_real(r, 1);
}

/* A valid polygon to start from: a box, a rounded box, a regular one or a
   hull of ordinary points. */
static ga2d_polygon fg_base_polygon(fz_reader *r)
{
    ga2d_polygon p;
    int kind = fz_pick(r, 4), i;
    switch (kind) {
    case 0: { /* one read a statement: arguments are evaluated in no set order */
        ga2d_real hw = fg_size(r, 0);
        p = ga2d_polygon_box(hw, fg_size(r, 0));
        break;
    }
    case 1: {
        ga2d_real hw = fg_size(r, 0), hh = fg_size(r, 0), lo = hw < hh ? hw : hh;
        p = ga2d_polygon_rounded_box(hw, hh, lo * (ga2d_real)fz_u8(r) / 256);
        break;
    }
    case 2: {
        int count = 3 + fz_pick(r, FG_MAXV - 2);
        p = ga2d_polygon_regular(count, fg_size(r, 0));
        break;
    }
    default: {
        ga2d_vec pts[16];
        int n = 3 + fz_pick(r, 14);
        for (i = 0; i < n; ++i) pts[i] = (i > 0 && fz_u8(r) < 16) ? pts[i - 1] : fg_vec(r, 0);
        if (ga2d_polygon_hull(pts, n, &p) != GA2D_OK) p = ga2d_polygon_box(1, (ga2d_real)0.5);
        break;
    }
    }
    if (p.count == 0) p = ga2d_polygon_box(1, (ga2d_real)0.5);
    return p;
}

/* The normals of a polygon recomputed from its edges (in double): each
   consistent with its edge whatever the outline's shape. */
static void fg_edge_normals(ga2d_polygon *p)
{
    int i;
    for (i = 0; i < p->count; ++i) {
        fg_d2 e = fg_sub(fg_d(p->vertices[(i + 1) % p->count]), fg_d(p->vertices[i]));
        double len = fg_len(e);
        if (len > 0) p->normals[i] = ga2d_vec_make(fz_narrow(e.y / len), fz_narrow(-e.x / len));
    }
}

static void fg_polygon(fz_reader *r, ga2d_polygon *p)
{
    static const double devs[10] = {1e-7, -1e-7, 4.9e-5, -4.9e-5, 9.9e-5, -9.9e-5, 1.01e-4, -1.01e-4, 1e-3, 0.5};
    int kind = fz_pick(r, 10), i, k;
    switch (kind) {
    case 0: case 1: case 2: case 3:
        *p = fg_base_polygon(r);
        if (fz_u8(r) < 96) p->radius = fg_radius(r);
        break;
    case 4: { /* one normal off unit, or tilted, by about the tolerance */
        double f = devs[fz_pick(r, 10)];
        *p = fg_base_polygon(r);
        i = fz_pick(r, p->count);
        if (fz_u8(r) & 1) {
            p->normals[i].x = fz_narrow((double)p->normals[i].x * sqrt(1 + f));
            p->normals[i].y = fz_narrow((double)p->normals[i].y * sqrt(1 + f));
        } else {
            double c = cos(f), s = sin(f), x = (double)p->normals[i].x, y = (double)p->normals[i].y;
            p->normals[i] = ga2d_vec_make(fz_narrow(c * x - s * y), fz_narrow(s * x + c * y));
        }
        break;
    }
    case 5: /* inconsistent outlines */
        *p = fg_base_polygon(r);
        k = fz_pick(r, 4);
        i = fz_pick(r, p->count);
        if (k == 0) { /* a zero edge */
            p->vertices[(i + 1) % p->count] = p->vertices[i];
        } else if (k == 1) { /* reversed: CW, with the normals of its edges */
            int a, b;
            for (a = 0, b = p->count - 1; a < b; ++a, --b) {
                ga2d_vec t = p->vertices[a];
                p->vertices[a] = p->vertices[b];
                p->vertices[b] = t;
            }
            fg_edge_normals(p);
        } else if (k == 2) { /* two vertices swapped: not convex, yet every normal fits its edge */
            int j = fz_pick(r, p->count);
            ga2d_vec t = p->vertices[i];
            p->vertices[i] = p->vertices[j];
            p->vertices[j] = t;
            fg_edge_normals(p);
        } else { /* a vertex moved anywhere, the normals kept */
            p->vertices[i] = fg_vec(r, fz_u8(r) < 64);
        }
        break;
    case 6: /* by hand: anything */
        memset(p, 0, sizeof *p);
        p->count = (int)(int8_t)fz_u8(r) % (FG_MAXV + 3);
        for (i = 0; i < FG_MAXV; ++i) {
            p->vertices[i] = fg_vec(r, 1);
            p->normals[i] = fg_vec(r, fz_u8(r) < 32);
        }
        p->radius = fg_radius(r);
        break;
    case 7: { /* scaled by a power of two: the normals stay exact */
        int e = (int)(int8_t)fz_u8(r) % 100;
        *p = fg_base_polygon(r);
        for (i = 0; i < p->count; ++i)
            p->vertices[i] = ga2d_vec_make(fz_narrow(ldexp((double)p->vertices[i].x, e)), fz_narrow(ldexp((double)p->vertices[i].y, e)));
        p->radius = fz_narrow(ldexp((double)p->radius, e));
        break;
    }
    case 8: /* a radius of any kind */
        *p = fg_base_polygon(r);
        p->radius = fz_real(r, 1);
        break;
    default: { /* a count out of range */
        static const int counts[6] = {0, 1, 2, -1, FG_MAXV + 1, 1000};
        *p = fg_base_polygon(r);
        p->count = counts[fz_pick(r, 6)];
        break;
    }
    }
}

/* Two ends: apart, equal, an ulp apart, or anything. */
static void fg_ends(fz_reader *r, ga2d_vec *p1, ga2d_vec *p2)
{
    int k = fz_pick(r, 8);
    *p1 = fg_vec(r, k == 7);
    if (k == 5) *p2 = *p1;
    else if (k == 6) *p2 = ga2d_vec_make(FG_NEXT(p1->x), p1->y);
    else *p2 = fg_vec(r, k == 7);
}

/* A ghost beyond an end: a neighbour anywhere, the straight extension,
   the end itself, or anything. */
static ga2d_vec fg_ghost(fz_reader *r, ga2d_vec end, ga2d_vec other)
{
    int k = fz_pick(r, 8);
    if (k < 4) return ga2d_vec_add(end, fg_vec(r, 0));
    if (k == 4) return ga2d_vec_sub(ga2d_vec_add(end, end), other);
    if (k == 5) return end;
    if (k == 6) return other;
    return fg_vec(r, 1);
}

static void fg_geometry(fz_reader *r, ga2d_geometry *g)
{
    int t = fz_pick(r, 16);
    memset(g, 0, sizeof *g);
    if (t < 3) {
        g->type = GA2D_SHAPE_CIRCLE;
        g->as.circle.center = fg_vec(r, fz_u8(r) < 24);
        g->as.circle.radius = fz_u8(r) < 200 ? fz_narrow((double)fz_u8(r) / 128) : fz_real(r, 1);
    } else if (t < 6) {
        g->type = GA2D_SHAPE_CAPSULE;
        fg_ends(r, &g->as.capsule.center1, &g->as.capsule.center2);
        g->as.capsule.radius = fg_radius(r);
    } else if (t < 10 || t == 15) {
        g->type = GA2D_SHAPE_POLYGON;
        fg_polygon(r, &g->as.polygon);
    } else if (t < 12) {
        g->type = GA2D_SHAPE_SEGMENT;
        fg_ends(r, &g->as.segment.point1, &g->as.segment.point2);
    } else if (t < 14) {
        ga2d_chain_segment *c = &g->as.chain_segment;
        g->type = GA2D_SHAPE_CHAIN_SEGMENT;
        fg_ends(r, &c->segment.point1, &c->segment.point2);
        c->ghost1 = fg_ghost(r, c->segment.point1, c->segment.point2);
        c->ghost2 = fg_ghost(r, c->segment.point2, c->segment.point1);
    } else {
        /* out of range (within the enum's bits: C++ allows those values) */
        g->type = (ga2d_shape_type)(GA2D_SHAPE_TYPE_COUNT + fz_pick(r, 3));
        fg_polygon(r, &g->as.polygon);
    }
}

/* A placement: mostly a unit rotor from an angle; sometimes a rotor off
   unit by about the collider's tolerance, or any two numbers.  *dev is
   how far |q|^2 is off 1 (in double). */
static ga2d_transform fg_transform(fz_reader *r, double *dev)
{
    static const double devs[12] = {1e-7, -1e-7, 5e-5, -5e-5, 9.9e-5, -9.9e-5, 1.01e-4, -1.01e-4, 2e-4, -2e-4, 1e-3, 0.5};
    ga2d_transform x;
    unsigned mode = fz_u8(r);
    x.p.x = fz_u8(r) < 224 ? fz_narrow((double)(int8_t)fz_u8(r) / 32) : fz_real(r, 4);
    x.p.y = fz_u8(r) < 224 ? fz_narrow((double)(int8_t)fz_u8(r) / 32) : fz_real(r, 4);
    if (mode < 176) {
        ga2d_real a = fz_u8(r) < 200 ? fz_narrow((double)fz_u8(r) * (6.283185307179586 / 256)) : fz_real(r, 4);
        x.q = ga2d_rotor_from_angle(fz_finite((double)a) ? a : 0);
    } else if (mode < 224) {
        double a = (double)fz_u8(r) * (6.283185307179586 / 256), f = sqrt(1 + devs[fz_pick(r, 12)]);
        x.q.c = fz_narrow(cos(a) * f);
        x.q.s = fz_narrow(sin(a) * f);
    } else {
        x.q.c = fz_real(r, 1);
        x.q.s = fz_real(r, 1);
    }
    *dev = fabs((double)x.q.c * (double)x.q.c + (double)x.q.s * (double)x.q.s - 1);
    return x;
}

/* --------------------------------------------------------------- cores */
/* A shape's core placed in double, relative to an origin, by its rotor
   normalized: 1 vertex (a point), 2 (a segment) or n (a convex polygon,
   CCW). */
typedef struct fg_core { int n; fg_d2 v[FG_MAXV]; double radius; } fg_core;

static fg_d2 fg_place_point(ga2d_vec v, ga2d_transform x, fg_d2 origin)
{
    double c = (double)x.q.c, s = (double)x.q.s, l = hypot(c, s), vx = (double)v.x, vy = (double)v.y;
    c /= l;
    s /= l;
    return fg_d2_make((double)x.p.x - origin.x + c * vx - s * vy, (double)x.p.y - origin.y + s * vx + c * vy);
}

static void fg_core_of(const ga2d_geometry *g, const fg_info *in, ga2d_transform x, fg_d2 origin, fg_core *c)
{
    int i;
    c->radius = in->radius;
    switch ((int)g->type) {
    case GA2D_SHAPE_CIRCLE:
        c->n = 1;
        c->v[0] = fg_place_point(g->as.circle.center, x, origin);
        break;
    case GA2D_SHAPE_CAPSULE:
        c->n = in->point ? 1 : 2;
        c->v[0] = fg_place_point(g->as.capsule.center1, x, origin);
        c->v[1] = fg_place_point(g->as.capsule.center2, x, origin);
        break;
    case GA2D_SHAPE_POLYGON:
        c->n = g->as.polygon.count;
        for (i = 0; i < c->n; ++i) c->v[i] = fg_place_point(g->as.polygon.vertices[i], x, origin);
        break;
    default: {
        const ga2d_segment *sg = (int)g->type == GA2D_SHAPE_CHAIN_SEGMENT ? &g->as.chain_segment.segment : &g->as.segment;
        c->n = in->point ? 1 : 2;
        c->v[0] = fg_place_point(sg->point1, x, origin);
        c->v[1] = fg_place_point(sg->point2, x, origin);
        break;
    }
    }
}

/* Distance from p to the segment ab, and the nearest point. */
static double fg_seg_dist(fg_d2 p, fg_d2 a, fg_d2 b, fg_d2 *q)
{
    fg_d2 e = fg_sub(b, a);
    double ee = fg_dot(e, e), t = ee > 0 ? fg_dot(fg_sub(p, a), e) / ee : 0;
    t = t < 0 ? 0 : (t > 1 ? 1 : t);
    *q = fg_add(a, fg_scale(e, t));
    return fg_len(fg_sub(p, *q));
}

/* Signed distance from p to a core (negative inside a polygon: the
   largest of its faces' separations), with the nearest point when outside. */
static double fg_point_dist(const fg_core *c, fg_d2 p, fg_d2 *q)
{
    int i, inside = c->n >= 3, best_interior = 0;
    double best = 1e300, face = -1e300;
    fg_d2 t;
    if (c->n == 1) {
        *q = c->v[0];
        return fg_len(fg_sub(p, c->v[0]));
    }
    for (i = 0; i < (c->n >= 3 ? c->n : 1); ++i) {
        fg_d2 a = c->v[i], b = c->v[(i + 1) % c->n], e = fg_sub(b, a);
        double d = fg_seg_dist(p, a, b, &t), s = fg_cross(e, fg_sub(p, a)) / fg_len(e);
        double along = fg_dot(fg_sub(p, a), e);
        int interior = along > 0 && along < fg_dot(e, e);
        /* the distances of p to a vertex and to the face beside it differ
           by (the face's reach past p's foot)^2 / (2 d): for a core much
           smaller than d they tie within d's rounding (a few eps d), and
           the vertex's direction is off the face's by size / d */
        double tie = 8 * FZ_EPS * (d + fg_len(p) + fg_len(a) + fg_len(b));
        /* the nearest point of a convex core lies on an edge that faces p
           (p on its outer side): the others' clamped ends can tie with it
           in rounding and would give another direction; so can a facing
           edge's clamped end tie with its neighbour's foot, which wins */
        int nearer = d < best - tie || (d <= best + tie && interior && !best_interior) ||
                     (d < best && interior == best_interior);
        if ((c->n < 3 || s <= 0) && nearer) {
            best = d;
            best_interior = interior;
            *q = t;
        }
        if (s < 0) inside = 0; /* right of a CCW edge: outside */
        face = fmax(face, -s);
    }
    return inside ? face : best;
}

/* Proper or touching crossing of ab and cd. */
static int fg_crosses(fg_d2 a, fg_d2 b, fg_d2 c, fg_d2 d)
{
    double d1 = fg_cross(fg_sub(b, a), fg_sub(c, a)), d2 = fg_cross(fg_sub(b, a), fg_sub(d, a));
    double d3 = fg_cross(fg_sub(d, c), fg_sub(a, c)), d4 = fg_cross(fg_sub(d, c), fg_sub(b, c));
    return ((d1 <= 0 && d2 >= 0) || (d1 >= 0 && d2 <= 0)) && ((d3 <= 0 && d4 >= 0) || (d3 >= 0 && d4 <= 0));
}

/* Distance between two cores; 0 when they meet. */
static double fg_core_dist(const fg_core *a, const fg_core *b)
{
    const fg_core *cs[2];
    int i, j, k;
    double best = 1e300;
    fg_d2 q;
    cs[0] = a;
    cs[1] = b;
    for (k = 0; k < 2; ++k) {
        const fg_core *p = cs[k], *o = cs[1 - k];
        for (i = 0; i < o->n; ++i) best = fmin(best, fg_point_dist(p, o->v[i], &q));
    }
    if (best <= 0) return 0;
    if (a->n >= 2 && b->n >= 2)
        for (i = 0; i < (a->n >= 3 ? a->n : 1); ++i)
            for (j = 0; j < (b->n >= 3 ? b->n : 1); ++j)
                if (fg_crosses(a->v[i], a->v[(i + 1) % a->n], b->v[j], b->v[(j + 1) % b->n])) return 0;
    return best;
}

/* The SAT value over a's face normals (a segment's two sides), as the
   collider takes it: the largest, over faces, of the least height of b's
   vertices above the face.  -1e300 when a has no faces. */
static double fg_sat(const fg_core *a, const fg_core *b)
{
    int i, j, faces = a->n >= 3 ? a->n : (a->n == 2 ? 2 : 0);
    double best = -1e300;
    for (i = 0; i < faces; ++i) {
        fg_d2 v0 = a->v[i], v1 = a->v[(i + 1) % a->n], e = fg_sub(v1, v0), nr;
        double lo = 1e300, l = fg_len(e);
        if (!(l > 0)) continue; /* a face too short for double here: no axis */
        nr = fg_d2_make(e.y / l, -e.x / l);
        for (j = 0; j < b->n; ++j) lo = fmin(lo, fg_dot(nr, fg_sub(b->v[j], v0)));
        best = fmax(best, lo);
    }
    return best;
}

/* Values compared field by field: a struct's padding (after an int, in
   the double build) is not part of its value. */
static int fg_manifold_equal(const ga2d_manifold *a, const ga2d_manifold *b)
{
    int i;
    if (a->count != b->count || memcmp(&a->normal, &b->normal, sizeof a->normal) != 0) return 0;
    for (i = 0; i < 2; ++i) {
        const ga2d_manifold_point *p = &a->points[i], *q = &b->points[i];
        if (memcmp(&p->point, &q->point, sizeof p->point) != 0 || memcmp(&p->anchor_a, &q->anchor_a, sizeof p->anchor_a) != 0 ||
            memcmp(&p->anchor_b, &q->anchor_b, sizeof p->anchor_b) != 0 ||
            memcmp(&p->separation, &q->separation, sizeof p->separation) != 0 ||
            memcmp(&p->normal_impulse, &q->normal_impulse, sizeof p->normal_impulse) != 0 ||
            memcmp(&p->tangent_impulse, &q->tangent_impulse, sizeof p->tangent_impulse) != 0 || p->id != q->id ||
            p->persisted != q->persisted)
            return 0;
    }
    return 1;
}

/* The same polygon: count, every vertex and normal, and the radius as a
   number (-0 is 0). */
static int fg_polygon_equal(const ga2d_polygon *a, const ga2d_polygon *b)
{
    return a->count == b->count && memcmp(a->vertices, b->vertices, sizeof a->vertices) == 0 &&
           memcmp(a->normals, b->normals, sizeof a->normals) == 0 && a->radius == b->radius;
}

/* ------------------------------------------------------------- collide */
typedef struct fg_side { const ga2d_geometry *g; const fg_info *in; ga2d_transform x; double dq; } fg_side;

/* What one call must give, whichever order. */
typedef struct fg_expect {
    int nf, inv, maybe; /* refusal reasons */
    double size;        /* |xa.p| + |xb.p| + reaches: overflow guard */
    double S, delta;    /* the pair's size and the two frames' rounding */
    double ndev;        /* how far a normal may be off unit (|n|^2) */
    ga2d_real units, margin;
} fg_expect;

static int fg_min_point(const ga2d_manifold *m)
{
    return m->count == 2 && m->points[1].separation < m->points[0].separation ? 1 : 0;
}

/* The checks of one order's answer, A first. */
static void fg_check_answer(const fg_side *A, const fg_side *B, const fg_expect *ex, int k, const ga2d_manifold *m)
{
    int i;
    double guard = 1e-3 * FZ_REAL_MAX;
    FUZZ_CHECK(k >= 0 && k <= 2 && m->count == k);
    if ((int)A->g->type == GA2D_SHAPE_CIRCLE || (int)B->g->type == GA2D_SHAPE_CIRCLE || A->in->point || B->in->point)
        FUZZ_CHECK(k <= 1);
    if (A->in->chain && B->in->chain) FUZZ_CHECK(k == 0);
    if (k == 0 || !(ex->size < guard)) return;
    {
        /* unit: |n|^2 = |q_a|^2 (|q_a|^2 |q_b|^2 |n_poly|^2 at most, through
           the frames the hulls pass), each off 1 by its deviation; the
           normalizations add a few eps */
        double nn = (double)m->normal.x * (double)m->normal.x + (double)m->normal.y * (double)m->normal.y;
        FUZZ_CHECK(fz_finite_vec(m->normal));
        FUZZ_CHECK(fabs(nn - 1) <= ex->ndev);
    }
    for (i = 0; i < k; ++i) {
        const ga2d_manifold_point *p = &m->points[i];
        double ra = fg_norm1(p->anchor_a), dp = fg_norm1(ga2d_vec_sub(B->x.p, A->x.p));
        FUZZ_CHECK(fz_finite_vec(p->point) && fz_finite_vec(p->anchor_a) && fz_finite_vec(p->anchor_b));
        FUZZ_CHECK(fz_finite((double)p->separation));
        FUZZ_CHECK(p->normal_impulse == 0 && p->tangent_impulse == 0);
        /* kept only within the speculative distance: the library compares
           the very value it stores */
        if (fz_finite((double)ex->margin)) FUZZ_CHECK((double)p->separation <= (double)ex->margin);
        /* the point relative to each origin: one rounding of a sum each */
        FUZZ_CHECK(fg_norm1(ga2d_vec_sub(p->point, ga2d_vec_add(A->x.p, p->anchor_a))) <=
                   4 * FZ_EPS * (fg_norm1(A->x.p) + fg_norm1(B->x.p) + ra) + 2 * FZ_TINY);
        FUZZ_CHECK(fg_norm1(ga2d_vec_sub(p->anchor_b, ga2d_vec_sub(p->anchor_a, ga2d_vec_sub(B->x.p, A->x.p)))) <=
                   4 * FZ_EPS * (ra + dp) + 2 * FZ_TINY);
    }
}

/* The distance oracle for convex shapes (both orders are held to it, so
   they agree with each other within it). */
static void fg_oracle(const fg_side *A, const fg_side *B, const fg_expect *ex, int k, const ga2d_manifold *m)
{
    fg_core ca, cb;
    fg_d2 origin = fg_d(A->x.p);
    double rsum = A->in->radius + B->in->radius, margin = (double)ex->margin, d = ex->delta;
    double slop = FG_SLOP * (double)ex->units;
    int i;
    if (!A->in->oracle || !B->in->oracle) return;
    /* within the range where products of sizes neither overflow nor lose
       every digit to underflow, and slop-sized tolerances mean something */
    if (!(ex->S <= 1e-3 * sqrt(FZ_REAL_MAX)) || !(ex->S >= 1e-12) || !fz_finite(margin) || !(d < 0.01 * slop)) return;
    /* a core within the rounding of where it is placed has no shape left
       to measure (a 1e-30 polygon 5 units away) */
    if ((!A->in->point && !(A->in->extent > 1e3 * d)) || (!B->in->point && !(B->in->extent > 1e3 * d))) return;
    fg_core_of(A->g, A->in, A->x, origin, &ca);
    fg_core_of(B->g, B->in, B->x, origin, &cb);
    if (ca.n == 1 || cb.n == 1) {
        /* a point (a circle's centre, or ends that coincide) against a core:
           one point at the signed distance, along the true direction */
        const fg_core *pt = cb.n == 1 ? &cb : &ca, *other = cb.n == 1 ? &ca : &cb;
        fg_d2 q, u;
        double sd = fg_point_dist(other, pt->v[0], &q), gap = sd - rsum;
        FG_TRACE((stderr, "  oracle point: sd %.9g gap %.9g delta %.3g k %d\n", sd, gap, d, k));
        if (gap > margin + 2 * d) FUZZ_CHECK(k == 0);
        if (gap < margin - 2 * d) FUZZ_CHECK(k == 1);
        if (k == 0) return;
        FUZZ_CHECK(fabs((double)m->points[0].separation - gap) <= 2 * d);
        if (sd > 64 * d) {
            /* from the core to the point, turned to run from A to B; off by
               the position error over the distance, plus the rotor's; and
               by the face-or-vertex choice: the foot's place along a face
               is t / L (t = d . e, d from the face's start to the point,
               e the edge), and with d and e each off by the frames'
               rounding (delta, 2 delta) it is off by up to 2 delta |d| / L
               + delta: a foot that near an end may be taken for the end,
               whose direction is off by that over sd (|d| ~ sd): 2 delta / L
               + delta / sd, L the core's shortest edge */
            double emin = 1e300;
            int j;
            for (j = 0; j < other->n && other->n >= 2; ++j)
                emin = fmin(emin, fg_len(fg_sub(other->v[(j + 1) % other->n], other->v[j])));
            u = fg_scale(fg_sub(pt->v[0], q), 1 / sd);
            if (pt == &ca) u = fg_scale(u, -1);
            FUZZ_CHECK(fg_len(fg_sub(fg_d(m->normal), u)) <= 5 * d / sd + 2 * d / emin + ex->ndev + 64 * FZ_EPS);
        }
        return;
    }
    {
        /* two cores with faces: every point lies on one core within the
           other's face slab, so its height is at least the face's SAT
           value, which is at least the best SAT less the 0.1 slop of the
           reference choice; once the SAT surely exceeds 0.1 slop the
           collider works on the closest features: one point at the true
           distance, or a face whose every vertex of the other core is
           within 0.1 slop of it */
        double sat = fmax(fg_sat(&ca, &cb), fg_sat(&cb, &ca)), dist = fg_core_dist(&ca, &cb);
        double lower = (sat > 0.1 * slop + 2 * d ? fmax(sat, dist) : sat) - 0.1 * slop;
        FG_TRACE((stderr, "  oracle hulls: sat %.9g dist %.9g rsum %.9g delta %.3g k %d\n", sat, dist, rsum, d, k));
        for (i = 0; i < k; ++i) FUZZ_CHECK((double)m->points[i].separation >= lower - rsum - 2 * d);
        if (dist - rsum > margin + 2 * d) FUZZ_CHECK(k == 0);
    }
}

#ifdef FUZZ_VERBOSE
static void fg_dump(const char *what, const ga2d_geometry *g, ga2d_transform x)
{
    int i;
    fprintf(stderr, "%s: type %d, x (%.9g %.9g | %.9g %.9g)\n", what, (int)g->type, (double)x.p.x, (double)x.p.y,
            (double)x.q.c, (double)x.q.s);
    switch ((int)g->type) {
    case GA2D_SHAPE_CIRCLE:
        fprintf(stderr, "  c (%.9g %.9g) r %.9g\n", (double)g->as.circle.center.x, (double)g->as.circle.center.y,
                (double)g->as.circle.radius);
        break;
    case GA2D_SHAPE_CAPSULE:
        fprintf(stderr, "  (%.9g %.9g)-(%.9g %.9g) r %.9g\n", (double)g->as.capsule.center1.x, (double)g->as.capsule.center1.y,
                (double)g->as.capsule.center2.x, (double)g->as.capsule.center2.y, (double)g->as.capsule.radius);
        break;
    case GA2D_SHAPE_POLYGON:
        fprintf(stderr, "  count %d r %.9g\n", g->as.polygon.count, (double)g->as.polygon.radius);
        for (i = 0; i < g->as.polygon.count && i < FG_MAXV && i >= 0; ++i)
            fprintf(stderr, "  v (%.9g %.9g) n (%.9g %.9g)\n", (double)g->as.polygon.vertices[i].x,
                    (double)g->as.polygon.vertices[i].y, (double)g->as.polygon.normals[i].x, (double)g->as.polygon.normals[i].y);
        break;
    case GA2D_SHAPE_SEGMENT:
        fprintf(stderr, "  (%.9g %.9g)-(%.9g %.9g)\n", (double)g->as.segment.point1.x, (double)g->as.segment.point1.y,
                (double)g->as.segment.point2.x, (double)g->as.segment.point2.y);
        break;
    default: {
        const ga2d_chain_segment *c = &g->as.chain_segment;
        fprintf(stderr, "  (%.9g %.9g)-(%.9g %.9g) ghosts (%.9g %.9g) (%.9g %.9g)\n", (double)c->segment.point1.x,
                (double)c->segment.point1.y, (double)c->segment.point2.x, (double)c->segment.point2.y, (double)c->ghost1.x,
                (double)c->ghost1.y, (double)c->ghost2.x, (double)c->ghost2.y);
        break;
    }
    }
}
static void fg_dump_manifold(const char *what, int k, const ga2d_manifold *m)
{
    int i;
    fprintf(stderr, "%s: %d, normal (%.9g %.9g)\n", what, k, (double)m->normal.x, (double)m->normal.y);
    for (i = 0; i < k && i < 2; ++i)
        fprintf(stderr, "  point (%.9g %.9g) sep %.9g id %x\n", (double)m->points[i].point.x, (double)m->points[i].point.y,
                (double)m->points[i].separation, (unsigned)m->points[i].id);
}
#define FG_DUMP(what, g, x) fg_dump(what, g, x)
#define FG_DUMP_M(what, k, m) fg_dump_manifold(what, k, m)
#else
#define FG_DUMP(what, g, x) ((void)0)
#define FG_DUMP_M(what, k, m) ((void)0)
#endif

static void fg_collide(const fg_side *A, const fg_side *B, ga2d_real units)
{
    ga2d_manifold m1, m2, sentinel, plain;
    fg_expect ex;
    int k1, k2, k, i, xnf, xinv, xmaybe;
    double dp = fg_norm1(ga2d_vec_sub(B->x.p, A->x.p));
    memset(&sentinel, 0x3C, sizeof sentinel);
    memset(&ex, 0, sizeof ex);
    FG_DUMP("A", A->g, A->x);
    FG_DUMP("B", B->g, B->x);
    /* what the transforms and the unit earn: NOT_FINITE for any value not
       finite; INVALID_ARGUMENT for |q|^2 off 1 by more than 1e-4 (either
       within 8 eps of that: the library rounds |q|^2 once or twice), or a
       unit <= 0 */
    xnf = !fz_finite_vec(A->x.p) || !fz_finite_vec(B->x.p) || !fz_finite((double)A->x.q.c) || !fz_finite((double)A->x.q.s) ||
          !fz_finite((double)B->x.q.c) || !fz_finite((double)B->x.q.s) || !fz_finite((double)units);
    xinv = xmaybe = 0;
    for (i = 0; i < 2; ++i) {
        double dq = i ? B->dq : A->dq;
        if (dq != dq) continue;  /* a component not finite: NOT_FINITE */
        if (fabs(dq - FG_UNIT_TOL) <= 8 * FZ_EPS) xmaybe = 1;
        else if (dq > FG_UNIT_TOL) xinv = 1;
    }
    if (!(units > 0)) xinv = 1;
    ex.nf = xnf || A->in->nf || B->in->nf;
    ex.inv = xinv || A->in->inv || B->in->inv;
    ex.maybe = xmaybe || A->in->maybe || B->in->maybe;
    ex.units = units;
    ex.margin = (ga2d_real)GA2D_SPECULATIVE_DISTANCE * units;
    ex.size = fg_norm1(A->x.p) + fg_norm1(B->x.p) + A->in->reach + B->in->reach;
    ex.S = dp + A->in->reach + B->in->reach;
    /* the two frames: the collider brings B into A's frame (the other
       order A into B's) with rotors off unit by dq each, and polygon
       normals off by ndev: a point moves by under (256 eps + 4 (dq_a +
       dq_b + ndev_a + ndev_b)) S, and a result below the normal range by a
       few of the smallest steps */
    ex.delta = (256 * FZ_EPS + 4 * (A->dq + B->dq + A->in->ndev + B->in->ndev)) * ex.S + 64 * FZ_TINY;
    ex.ndev = 1.01 * (2 * A->dq + 2 * B->dq + A->in->ndev + B->in->ndev) + 64 * FZ_EPS;

    m1 = sentinel;
    m2 = sentinel;
    k1 = ga2d_collide_shapes_scaled(A->g, A->x, B->g, B->x, units, &m1);
    k2 = ga2d_collide_shapes_scaled(B->g, B->x, A->g, A->x, units, &m2);
    FG_TRACE((stderr, "collide: %d / %d (nf %d inv %d maybe %d) units %g\n", k1, k2, ex.nf, ex.inv, ex.maybe, (double)units));
    FG_DUMP_M("A, B", k1, &m1);
    FG_DUMP_M("B, A", k2, &m2);
    /* the input checks look at both shapes alike: the same refusal */
    FUZZ_CHECK(k1 == k2 || (k1 >= 0 && k2 >= 0));
    for (i = 0; i < 2; ++i) {
        int kk = i ? k2 : k1;
        const ga2d_manifold *mm = i ? &m2 : &m1;
        if (kk < 0) {
            FUZZ_CHECK(ex.nf || ex.inv || ex.maybe);
            FUZZ_CHECK((kk == -(int)GA2D_ERR_NOT_FINITE && ex.nf) || (kk == -(int)GA2D_ERR_INVALID_ARGUMENT && (ex.inv || ex.maybe)));
            FUZZ_CHECK(memcmp(mm, &sentinel, sizeof *mm) == 0);
        } else {
            FUZZ_CHECK(!ex.nf && !ex.inv);
        }
    }
    if (k1 < 0) return;
    fg_check_answer(A, B, &ex, k1, &m1);
    fg_check_answer(B, A, &ex, k2, &m2);
    if (!(ex.size < 1e-3 * FZ_REAL_MAX)) return;
    fg_oracle(A, B, &ex, k1, &m1);
    fg_oracle(B, A, &ex, k2, &m2);

    /* the unscaled form is the scaled one at 1 */
    if (units == 1) {
        plain = sentinel;
        k = ga2d_collide_shapes(A->g, A->x, B->g, B->x, &plain);
        FUZZ_CHECK(k == k1 && fg_manifold_equal(&plain, &m1));
    }
    /* two polygons: what ga2d_collide_polygons_scaled gives */
    if ((int)A->g->type == GA2D_SHAPE_POLYGON && (int)B->g->type == GA2D_SHAPE_POLYGON) {
        plain = sentinel;
        k = ga2d_collide_polygons_scaled(&A->g->as.polygon, A->x, &B->g->as.polygon, B->x, units, &plain);
        FUZZ_CHECK(k == k1 && fg_manifold_equal(&plain, &m1));
    }

    if (A->in->chain != B->in->chain) {
        /* a chain segment against anything else: computed in the chain's
           frame in both orders, so mirrored bit for bit */
        const fg_side *C = A->in->chain ? A : B, *O = A->in->chain ? B : A;
        const ga2d_manifold *mc = A->in->chain ? &m1 : &m2, *mo = A->in->chain ? &m2 : &m1;
        FUZZ_CHECK(k1 == k2);
        FUZZ_CHECK(mc->normal.x == -mo->normal.x && mc->normal.y == -mo->normal.y);
        for (i = 0; i < k1; ++i) {
            const ga2d_manifold_point *p = &mc->points[i], *q = &mo->points[i];
            FUZZ_CHECK(memcmp(&p->point, &q->point, sizeof p->point) == 0 && p->separation == q->separation);
            FUZZ_CHECK(memcmp(&p->anchor_a, &q->anchor_b, sizeof p->anchor_a) == 0 &&
                       memcmp(&p->anchor_b, &q->anchor_a, sizeof p->anchor_b) == 0);
            FUZZ_CHECK(p->id == (q->id ^ (1u << 16)));
        }
        if (k1 > 0) {
            /* the plain segment's manifold, kept; its normal to the left
               of point1 -> point2 (rotated back by C's rotor: the sign
               survives a rounding of 16 eps |e|) */
            ga2d_geometry seg;
            ga2d_manifold ms = sentinel;
            const ga2d_segment *s = &C->g->as.chain_segment.segment;
            fg_d2 e = fg_sub(fg_d(s->point2), fg_d(s->point1)), u;
            double c = (double)C->x.q.c, sn = (double)C->x.q.s, nx = (double)mc->normal.x, ny = (double)mc->normal.y;
            memset(&seg, 0, sizeof seg);
            seg.type = GA2D_SHAPE_SEGMENT;
            seg.as.segment = *s;
            k = ga2d_collide_shapes_scaled(&seg, C->x, O->g, O->x, units, &ms);
            u = fg_d2_make(c * nx + sn * ny, c * ny - sn * nx);
            FUZZ_CHECK(fg_dot(u, fg_d2_make(-e.y, e.x)) >= -16 * FZ_EPS * fg_len(e) * fg_len(u));
            if (!(k == k1 && fg_manifold_equal(&ms, mc))) {
                /* else the face, snapped at a valley (the chain turns left
                   at an end; the turn of unit directions rounds, so which
                   joins are valleys is the library's) and carried over the
                   neighbour: the face's own normal, every point's reference the segment's front
                   face (A's face 1, whose ends are features 1 and 0), none made
                   from B's face */
                FUZZ_CHECK(fabs(u.x * e.x + u.y * e.y) <= 16 * FZ_EPS * fg_len(e) * fg_len(u));
                for (i = 0; i < k1; ++i) FUZZ_CHECK(((mc->points[i].id >> 8) & 0x1ff) <= 1);
            }
        }
    } else if (!A->in->chain) {
        /* counts where well defined: never none in one order with a point
           well inside the margin in the other (both orders bound the
           separation below by the same geometry, within the 0.1 slop of the
           reference choice and the frames' rounding, each) */
        /* for shapes a maker could have made: the collider's per-edge
           check also takes clockwise and non-convex outlines, whose
           answers promise no symmetry */
        int formed = (A->in->oracle || (int)A->g->type != GA2D_SHAPE_POLYGON) &&
                     (B->in->oracle || (int)B->g->type != GA2D_SHAPE_POLYGON);
        /* and sizes whose squares the collider can form (its edge and
           offset lengths squared: beyond sqrt of the real range they
           overflow, and the header promises nothing there) */
        if (!(ex.S <= 1e-3 * sqrt(FZ_REAL_MAX))) formed = 0;
        if (formed && (k1 == 0) != (k2 == 0)) {
            const ga2d_manifold *mm = k1 ? &m1 : &m2;
            double s = (double)mm->points[fg_min_point(mm)].separation;
            FUZZ_CHECK(s > (double)ex.margin - 0.2 * FG_SLOP * (double)units - 4 * ex.delta);
        }
    }
}

/* ---------------------------------------------------------------- mass */
/* The refusal reasons of a mass function, worked out here. */
static void fg_check_mass_result(ga2d_result r, int nf, int inv, int too_large_ok, int must_ok, const ga2d_mass *m,
                                 const ga2d_mass *sentinel, const ga2d_mass *plain)
{
    FUZZ_CHECK((int)r >= 0 && r < GA2D_RESULT_COUNT);
    if (nf || inv) {
        FUZZ_CHECK((r == GA2D_ERR_NOT_FINITE && nf) || (r == GA2D_ERR_INVALID_ARGUMENT && inv));
    } else if (must_ok) {
        FUZZ_CHECK(r == GA2D_OK);
    } else {
        FUZZ_CHECK(r == GA2D_OK || (r == GA2D_ERR_TOO_LARGE && too_large_ok));
    }
    if (r != GA2D_OK) {
        FUZZ_CHECK(memcmp(m, sentinel, sizeof *m) == 0);
        FUZZ_CHECK(plain->mass == 0 && plain->inertia == 0 && plain->center.x == 0 && plain->center.y == 0);
        return;
    }
    FUZZ_CHECK(memcmp(m, plain, sizeof *m) == 0);
    FUZZ_CHECK(fz_finite((double)m->mass) && fz_finite((double)m->inertia) && fz_finite_vec(m->center));
    FUZZ_CHECK(m->mass >= 0 && m->inertia >= 0);
}

static void fg_mass_circle(const ga2d_circle *c, ga2d_real rho)
{
    ga2d_mass m, sentinel, plain;
    ga2d_result r;
    double rr = (double)c->radius, p = (double)rho, exact, big;
    int nf = !fz_finite((double)rho) || !fz_finite(rr) || !fz_finite_vec(c->center);
    int inv = (fz_finite((double)rho) && rho < 0) || (fz_finite(rr) && rr < 0);
    memset(&sentinel, 0x5A, sizeof sentinel);
    m = sentinel;
    r = ga2d_circle_mass_checked(c, rho, &m);
    plain = ga2d_circle_mass(c, rho);
    exact = p * 3.141592653589793 * rr * rr;
    /* TOO_LARGE only where a term the formula forms overflows (rho pi, rho
       pi r, m, m r, m r^2), each judged with a factor 4 to spare */
    big = fmax(fmax(p * 4, p * 4 * rr), fmax(exact * 4, fmax(exact * rr * 4, exact * rr * rr * 4)));
    FG_TRACE((stderr, "circle mass r %g rho %g: %s\n", rr, p, ga2d_result_string(r)));
    fg_check_mass_result(r, nf, inv, 1, !nf && !inv && big < FZ_REAL_MAX, &m, &sentinel, &plain);
    if (r != GA2D_OK) return;
    FUZZ_CHECK(memcmp(&m.center, &c->center, sizeof m.center) == 0);
    /* four roundings (pi included), or an underflow at each by up to the
       smallest subnormal, carried through the factors of r after it */
    FUZZ_CHECK(fabs((double)m.mass - exact) <= 6 * FZ_EPS * exact + 8 * FZ_TINY * (1 + rr) * (1 + rr));
    FUZZ_CHECK(fabs((double)m.inertia - exact * rr * rr / 2) <=
               8 * FZ_EPS * exact * rr * rr / 2 + 8 * FZ_TINY * (1 + rr) * (1 + rr) * (1 + rr) * (1 + rr));
}

static void fg_mass_capsule(const ga2d_capsule *c, ga2d_real rho)
{
    ga2d_mass m, sentinel, plain;
    ga2d_result r;
    double rr = (double)c->radius, p = (double)rho, L, mr, mh, d0, mass, inertia, big;
    fg_d2 e;
    int nf = !fz_finite((double)rho) || !fz_finite(rr) || !fz_finite_vec(c->center1) || !fz_finite_vec(c->center2);
    int inv = (fz_finite((double)rho) && rho < 0) || (fz_finite(rr) && rr < 0);
    memset(&sentinel, 0x5A, sizeof sentinel);
    m = sentinel;
    r = ga2d_capsule_mass_checked(c, rho, &m);
    plain = ga2d_capsule_mass(c, rho);
    e = fg_sub(fg_d(c->center2), fg_d(c->center1));
    L = fg_len(e);
    /* independently: a rectangle 2r x L and a disc of radius r (two half
       discs) whose halves' centroids stand 4r/(3 pi) beyond the ends */
    mr = p * 2 * rr * L;
    mh = p * 3.141592653589793 * rr * rr / 2;
    d0 = 4 * rr / (3 * 3.141592653589793);
    mass = mr + 2 * mh;
    inertia = mr * (L * L + 4 * rr * rr) / 12 + 2 * (mh * (rr * rr / 2 - d0 * d0) + mh * (L / 2 + d0) * (L / 2 + d0));
    big = fmax(fmax(fmax(fabs(e.x), fabs(e.y)) * 4, L * L * 4), fmax(fmax(p * 8 * (rr + 1) * (L + 1), mass * 4), inertia * 4));
    big = fmax(big, fmax(mr * (L * L + 4 * rr * rr) * 4, mh * (rr * rr + L * L + L * rr) * 8));
    big = fmax(big, fmax(fg_norm1(c->center1), fg_norm1(c->center2)) * 4);
    big = fmax(big, rr * rr * 8); /* r^2 even at density 0: 0 times an overflow is no number */
    FG_TRACE((stderr, "capsule mass L %g r %g rho %g: %s\n", L, rr, p, ga2d_result_string(r)));
    fg_check_mass_result(r, nf, inv, 1, !nf && !inv && big < FZ_REAL_MAX, &m, &sentinel, &plain);
    if (r != GA2D_OK) return;
    /* a few roundings each of sums of positive terms (the length, a
       scaled hypot, within 2 eps), or underflow by the smallest subnormal */
    FUZZ_CHECK(fabs((double)m.mass - mass) <= 16 * FZ_EPS * mass + 16 * FZ_TINY * (1 + L + rr) * (1 + L + rr));
    if (inertia > 1e3 * FZ_REAL_MIN / FZ_EPS)
        FUZZ_CHECK(fabs((double)m.inertia - inertia) <= 32 * FZ_EPS * inertia + 16 * FZ_TINY * pow(1 + L + rr, 4));
    /* the midpoint: c1 + (c2 - c1)/2, two roundings of values <= |c1| + |c2| */
    FUZZ_CHECK(fabs((double)m.center.x - ((double)c->center1.x + (double)c->center2.x) / 2) <=
               2 * FZ_EPS * (fabs((double)c->center1.x) + fabs((double)c->center2.x)) + 2 * FZ_TINY);
    FUZZ_CHECK(fabs((double)m.center.y - ((double)c->center1.y + (double)c->center2.y) / 2) <=
               2 * FZ_EPS * (fabs((double)c->center1.y) + fabs((double)c->center2.y)) + 2 * FZ_TINY);
    if (c->center1.x == c->center2.x && c->center1.y == c->center2.y) {
        /* zero length: the disc */
        ga2d_circle disc;
        ga2d_mass dm;
        disc.center = c->center1;
        disc.radius = c->radius;
        if (ga2d_circle_mass_checked(&disc, rho, &dm) == GA2D_OK)
            FUZZ_CHECK(fabs((double)dm.mass - (double)m.mass) <= 8 * FZ_EPS * (double)m.mass + 16 * FZ_TINY * (1 + rr) * (1 + rr));
    }
}

/* A polygon with its radius.  Consistent or not, it never crashes and
   refuses with a code; a valid one (consistent, strictly convex, within
   GA2D_MAX_COORDINATE, its radius within its extent) at a density up to
   1e6 is OK, with the rounded area A + r P + pi r^2. */
static void fg_mass_polygon(const ga2d_polygon *p, const fg_info *in, ga2d_real rho)
{
    ga2d_mass m, sentinel, plain;
    ga2d_result r;
    int n = p->count, i, valid = in->oracle;
    double rr = (double)p->radius, d = (double)rho, area2 = 0, per = 0, L = 0, lox = 0, hix = 0, loy = 0, hiy = 0, exact;
    memset(&sentinel, 0x5A, sizeof sentinel);
    m = sentinel;
    r = ga2d_polygon_mass_checked(p, rho, &m);
    plain = ga2d_polygon_mass(p, rho);
    FG_TRACE((stderr, "polygon mass n %d r %g rho %g: %s\n", n, rr, d, ga2d_result_string(r)));
    FUZZ_CHECK((int)r >= 0 && r < GA2D_RESULT_COUNT);
    if (n < 3) FUZZ_CHECK(r == GA2D_ERR_TOO_FEW_POINTS);
    else if (n > FG_MAXV) FUZZ_CHECK(r == GA2D_ERR_TOO_MANY_POINTS);
    else if (!fz_finite(d) || !fz_finite(rr)) FUZZ_CHECK(r == GA2D_ERR_NOT_FINITE);
    else if (d < 0 || rr < 0) FUZZ_CHECK(r == GA2D_ERR_INVALID_ARGUMENT);
    else {
        /* a vertex that is not finite may be named so, or found degenerate */
        int bad = 0;
        for (i = 0; i < n; ++i) bad |= !fz_finite_vec(p->vertices[i]);
        FUZZ_CHECK(r == GA2D_OK || r == GA2D_ERR_DEGENERATE || r == GA2D_ERR_TOO_LARGE || (r == GA2D_ERR_NOT_FINITE && bad));
    }
    if (r != GA2D_OK) {
        FUZZ_CHECK(memcmp(&m, &sentinel, sizeof m) == 0);
        FUZZ_CHECK(plain.mass == 0 && plain.inertia == 0 && plain.center.x == 0 && plain.center.y == 0);
    } else {
        FUZZ_CHECK(memcmp(&m, &plain, sizeof m) == 0);
        FUZZ_CHECK(fz_finite((double)m.mass) && fz_finite((double)m.inertia) && fz_finite_vec(m.center));
    }
    if (!valid || n < 3 || n > FG_MAXV) return;
    lox = hix = (double)p->vertices[0].x;
    loy = hiy = (double)p->vertices[0].y;
    for (i = 0; i < n; ++i) {
        fg_d2 a = fg_d(p->vertices[i]), b = fg_d(p->vertices[(i + 1) % n]);
        if (fg_norm1(p->vertices[i]) > (double)GA2D_MAX_COORDINATE) valid = 0;
        area2 += fg_cross(fg_sub(a, fg_d(p->vertices[0])), fg_sub(b, fg_d(p->vertices[0])));
        per += fg_len(fg_sub(b, a));
        lox = fmin(lox, a.x);
        hix = fmax(hix, a.x);
        loy = fmin(loy, a.y);
        hiy = fmax(hiy, a.y);
    }
    L = fmax(hix - lox, hiy - loy);
    /* OK promised where no term can overflow: the inertia's sums grow as
       the density times the fourth power of the reach */
    {
        double reach = in->reach;
        if (!valid || !(rr <= L) || !(d >= 0 && d <= 1e6) || !(L * L * 1e-5 >= 64 * FZ_REAL_MIN / FZ_EPS) ||
            !(64 * (d + 1) * reach * reach * reach * reach < FZ_REAL_MAX))
            return;
    }
    FUZZ_CHECK(r == GA2D_OK);
    if (r != GA2D_OK) return;
    FUZZ_CHECK(m.mass >= 0 && m.inertia >= 0);
    /* the core as the polygon harness bounds it (5 n eps L^2), the strips
       and sectors a few eps each of r P and pi r^2 (an atan2 and a sine per
       corner): */
    exact = d * (area2 / 2 + rr * per + 3.141592653589793 * rr * rr);
    FUZZ_CHECK(fabs((double)m.mass - exact) <= d * (5 * n * FZ_EPS * L * L + 16 * n * FZ_EPS * (rr * per + 4 * rr * rr)) +
                                                  FZ_EPS * exact + 16 * n * FZ_TINY * (1 + d));
    if (d > 0 && exact > 1e-30 && exact < 1e30) {
        /* the centroid within the rounded outline's box */
        double slack = 16 * FZ_EPS * (L + rr + fabs((double)m.center.x) + fabs((double)m.center.y));
        FUZZ_CHECK((double)m.center.x >= lox - rr - slack && (double)m.center.x <= hix + rr + slack);
        FUZZ_CHECK((double)m.center.y >= loy - rr - slack && (double)m.center.y <= hiy + rr + slack);
        /* every point within sqrt2 (L + 2r) of the centroid */
        if (exact * L * L >= 64 * FZ_REAL_MIN / FZ_EPS)
            FUZZ_CHECK((double)m.inertia <= 2 * exact * (L + 2 * rr) * (L + 2 * rr) * (1 + 64 * FZ_EPS));
    }
}

static void fg_masses(fz_reader *r, const ga2d_geometry *g, const fg_info *in)
{
    ga2d_real rho = fz_u8(r) < 200 ? fz_narrow((double)fz_u8(r) / 16) : fz_real(r, 4);
    switch ((int)g->type) {
    case GA2D_SHAPE_CIRCLE: fg_mass_circle(&g->as.circle, rho); break;
    case GA2D_SHAPE_CAPSULE: {
        fg_mass_capsule(&g->as.capsule, rho);
        /* the circle at one end, too */
        ga2d_circle c;
        c.center = g->as.capsule.center1;
        c.radius = g->as.capsule.radius;
        fg_mass_circle(&c, rho);
        break;
    }
    case GA2D_SHAPE_POLYGON: fg_mass_polygon(&g->as.polygon, in, rho); break;
    default: break;
    }
}

/* -------------------------------------------------------------- makers */
static ga2d_real fg_maker_real(fz_reader *r)
{
    unsigned k = fz_u8(r);
    if (k < 200) return fz_narrow((double)(1 + fz_u8(r)) / 32);
    return fz_real(r, 4);
}

static void fg_makers(fz_reader *r)
{
    ga2d_real hw = fg_maker_real(r), hh = fg_maker_real(r), rad;
    ga2d_polygon chk, plain;
    ga2d_result res;
    fg_info in;
    int nf, inv, large, n, i;
    unsigned k = fz_u8(r);
    /* the radius: a share of the smaller half-extent, exactly it, or anything */
    if (k < 160) rad = (hw < hh ? hw : hh) * (ga2d_real)fz_u8(r) / 256;
    else if (k < 200) rad = hw < hh ? hw : hh;
    else if (k < 216) rad = 0;
    else rad = fz_real(r, 1);
    if (!fz_finite((double)rad)) rad = fz_u8(r) & 1 ? rad : 0;

    memset(&chk, 0xA5, sizeof chk);
    res = ga2d_polygon_rounded_box_checked(hw, hh, rad, &chk);
    plain = ga2d_polygon_rounded_box(hw, hh, rad);
    FG_TRACE((stderr, "rounded box %g %g r %g: %s\n", (double)hw, (double)hh, (double)rad, ga2d_result_string(res)));
    nf = !fz_finite((double)hw) || !fz_finite((double)hh) || !fz_finite((double)rad);
    inv = (fz_finite((double)hw) && !(hw > 0)) || (fz_finite((double)hh) && !(hh > 0)) || (fz_finite((double)rad) && rad < 0) ||
          (!nf && !(hw > rad && hh > rad));
    large = (fz_finite((double)hw) && (double)hw > (double)GA2D_MAX_COORDINATE) ||
            (fz_finite((double)hh) && (double)hh > (double)GA2D_MAX_COORDINATE);
    FUZZ_CHECK(fg_polygon_equal(&chk, &plain)); /* the same polygon, or the same zeros */
    if (nf || inv || large) {
        FUZZ_CHECK((res == GA2D_ERR_NOT_FINITE && nf) || (res == GA2D_ERR_INVALID_ARGUMENT && inv) ||
                   (res == GA2D_ERR_TOO_LARGE && large));
    } else if (rad == 0) {
        FUZZ_CHECK(res == GA2D_OK);
    } else {
        /* the core is a box of cx x cy (both > 0: hw > r gives hw - r > 0);
           ga2d_polygon_make refuses it only when thin or tiny */
        double cx = (double)(hw - rad), cy = (double)(hh - rad);
        FUZZ_CHECK(res == GA2D_OK || res == GA2D_ERR_REPEATED_POINTS || res == GA2D_ERR_DEGENERATE ||
                   res == GA2D_ERR_COLLINEAR_POINTS);
        if (fmin(cx, cy) >= 1e-3 * fmax(cx, cy) && fmax(cx, cy) >= 1e-10) FUZZ_CHECK(res == GA2D_OK);
    }
    if (res != GA2D_OK) {
        FUZZ_CHECK(chk.count == 0);
    } else {
        ga2d_aabb box = ga2d_polygon_aabb(&chk, ga2d_transform_identity());
        FUZZ_CHECK(chk.count == 4 && chk.radius == rad);
        memset(&in, 0, sizeof in);
        fg_classify_polygon(&chk, &in);
        FUZZ_CHECK(!in.nf && !in.inv);
        /* the outline spans 2 hw x 2 hh: (hw - r) + r, two roundings */
        FUZZ_CHECK(fabs((double)box.upper.x - (double)hw) <= 2 * FZ_EPS * (double)hw &&
                   fabs((double)box.lower.x + (double)hw) <= 2 * FZ_EPS * (double)hw);
        FUZZ_CHECK(fabs((double)box.upper.y - (double)hh) <= 2 * FZ_EPS * (double)hh &&
                   fabs((double)box.lower.y + (double)hh) <= 2 * FZ_EPS * (double)hh);
        if (rad == 0) {
            ga2d_polygon b = ga2d_polygon_box(hw, hh);
            FUZZ_CHECK(fg_polygon_equal(&b, &chk));
        }
    }

    /* regular n-gons */
    n = fz_pick(r, FG_MAXV + 5) - 2;
    rad = fg_maker_real(r);
    memset(&chk, 0xA5, sizeof chk);
    res = ga2d_polygon_regular_checked(n, rad, &chk);
    plain = ga2d_polygon_regular(n, rad);
    FG_TRACE((stderr, "regular %d r %g: %s\n", n, (double)rad, ga2d_result_string(res)));
    FUZZ_CHECK(fg_polygon_equal(&chk, &plain));
    if (n < 3 || n > FG_MAXV || !fz_finite((double)rad) || !(rad > 0)) {
        FUZZ_CHECK((res == GA2D_ERR_TOO_FEW_POINTS && n < 3) || (res == GA2D_ERR_TOO_MANY_POINTS && n > FG_MAXV) ||
                   (res == GA2D_ERR_NOT_FINITE && !fz_finite((double)rad)) ||
                   (res == GA2D_ERR_INVALID_ARGUMENT && fz_finite((double)rad) && !(rad > 0)));
    } else {
        FUZZ_CHECK(res == GA2D_OK || res == GA2D_ERR_TOO_LARGE || res == GA2D_ERR_DEGENERATE || res == GA2D_ERR_REPEATED_POINTS ||
                   res == GA2D_ERR_COLLINEAR_POINTS);
        if ((double)rad >= 1e-6 && (double)rad <= (double)GA2D_MAX_COORDINATE / 2) FUZZ_CHECK(res == GA2D_OK);
    }
    if (res != GA2D_OK) {
        FUZZ_CHECK(chk.count == 0);
    } else {
        FUZZ_CHECK(chk.count == n && chk.radius == 0);
        FUZZ_CHECK(chk.vertices[0].x == rad && chk.vertices[0].y == 0);
        /* on the circle: r cos and r sin rounded, 4 eps of r */
        for (i = 0; i < n; ++i) FUZZ_CHECK(fabs(fg_len(fg_d(chk.vertices[i])) - (double)rad) <= 4 * FZ_EPS * (double)rad);
        memset(&in, 0, sizeof in);
        fg_classify_polygon(&chk, &in);
        FUZZ_CHECK(!in.nf && !in.inv);
    }
    FUZZ_CHECK(ga2d_polygon_rounded_box_checked(1, 1, 0, NULL) == GA2D_ERR_INVALID_ARGUMENT);
    FUZZ_CHECK(ga2d_polygon_regular_checked(3, 1, NULL) == GA2D_ERR_INVALID_ARGUMENT);
}


/* ------------------------------------------------- queries (issue 25) */
/* The world-free queries on the two geometries, read after everything
   above (so older inputs keep their meaning): a ray cast through the typed
   functions and ga2d_ray_cast_shape, GJK distance with a cache (zeroed,
   reused, or garbage), a shape cast and time of impact.  Tolerances:
   S is the size of what is placed (1-norms of origins, translations and
   the proxies' reach); a point placed by a transform, or moved along a
   ray, rounds by a few eps of S per operation, and a rotor off unit by
   dq scales it by up to dq: 64 eps S + 4 dq S covers every chain of
   operations here with a margin of more than 4, and FZ_TINY * 4 a
   result that underflows.  Checks against exact geometry run only for
   "ordinary" inputs (every value finite, S < 1e6, rotors unit within
   1e-6), where that bound is meaningful. */
static double fg_proxy_reach(const ga2d_shape_proxy *p)
{
    double m = 0;
    int i;
    for (i = 0; i < p->count && i < FG_MAXV; ++i)
        if (fg_norm1(p->points[i]) > m) m = fg_norm1(p->points[i]);
    return m + fabs((double)p->radius);
}

static int fg_finite_proxy(const ga2d_shape_proxy *p)
{
    int i;
    for (i = 0; i < p->count && i < FG_MAXV; ++i)
        if (!fz_finite_vec(p->points[i])) return 0;
    return fz_finite((double)p->radius);
}

/* A proxy: a shape's own (through ga2d_shape_proxy_of), or by hand from
   any bytes (a count from -1 to FG_MAXV + 1, any radius). */
static ga2d_shape_proxy fg_proxy(fz_reader *r, const ga2d_geometry *g)
{
    ga2d_shape_proxy p;
    ga2d_vec pts[FG_MAXV + 2];
    int n, i;
    unsigned k = fz_u8(r);
    if (k < 192) return ga2d_shape_proxy_of(g);
    n = (int)(fz_u8(r) % (FG_MAXV + 3)) - 1;
    for (i = 0; i < FG_MAXV + 2; ++i) {
        pts[i].x = k < 240 ? fz_narrow((double)(int8_t)fz_u8(r) / 32) : fz_real(r, 2);
        pts[i].y = k < 240 ? fz_narrow((double)(int8_t)fz_u8(r) / 32) : fz_real(r, 2);
    }
    p = ga2d_make_proxy(pts, n, k < 240 ? fz_narrow((double)fz_u8(r) / 256) : fz_real(r, 1));
    FUZZ_CHECK(p.count == (n < 1 ? 0 : n > FG_MAXV ? FG_MAXV : n));
    return p;
}

/* Whether a proxy is refused: a count out of range or a negative radius
   (INVALID_ARGUMENT), a value not finite (NOT_FINITE). */
static int fg_proxy_errs(const ga2d_shape_proxy *p)
{
    return p->count < 1 || p->count > FG_MAXV || !fg_finite_proxy(p) || p->radius < 0;
}

/* A transform as the collider reads it: 2 refused (values not finite, a
   rotor off unit past its tolerance), 1 either (within rounding of the
   tolerance), 0 accepted. */
static int fg_xf_bad(ga2d_transform x, double dev)
{
    if (!fz_finite_vec(x.p) || !fz_finite((double)x.q.c) || !fz_finite((double)x.q.s)) return 2;
    if (dev > 0.9 * FG_UNIT_TOL && dev < 1.1 * FG_UNIT_TOL) return 1;
    return dev > FG_UNIT_TOL ? 2 : 0;
}

/* An answer: with no reason to refuse, OK; with one, a named refusal
   (NOT_FINITE, INVALID_ARGUMENT or TOO_LARGE: which reason is reported
   first is the library's order); within rounding of one, either. */
static void fg_check_errs(ga2d_result r, int must_fail, int may_fail)
{
    FUZZ_CHECK((int)r >= 0 && r < GA2D_RESULT_COUNT);
    if (r != GA2D_OK) FUZZ_CHECK(r == GA2D_ERR_NOT_FINITE || r == GA2D_ERR_INVALID_ARGUMENT || r == GA2D_ERR_TOO_LARGE);
    if (must_fail) FUZZ_CHECK(r != GA2D_OK);
    else if (!may_fail) FUZZ_CHECK(r == GA2D_OK);
}

static int fg_unit_or_zero(ga2d_vec n, double tol, int zero_ok)
{
    double l2 = (double)n.x * (double)n.x + (double)n.y * (double)n.y;
    return fabs(l2 - 1) <= tol || (zero_ok && l2 == 0);
}

/* A ray hit's promises: fraction in [0, 1], a unit normal (within the
   polygon normals' and the rotor's own deviation), and the point on the
   ray at that fraction. */
static void fg_check_ray_hit(const ga2d_ray_result *h, ga2d_vec o, ga2d_vec t, double ntol, double ptol, int ordinary)
{
    if (!h->hit) {
        FUZZ_CHECK(h->fraction == 0 && h->point.x == 0 && h->point.y == 0 && h->normal.x == 0 && h->normal.y == 0);
        return;
    }
    FG_TRACE((stderr, "ray hit o (%.9g %.9g) t (%.9g %.9g): f %.9g p (%.9g %.9g) n (%.9g %.9g)\n", (double)o.x, (double)o.y,
              (double)t.x, (double)t.y, (double)h->fraction, (double)h->point.x, (double)h->point.y, (double)h->normal.x,
              (double)h->normal.y));
    FUZZ_CHECK(h->fraction >= 0 && h->fraction <= 1);
    FUZZ_CHECK(fz_finite_vec(h->point) && fz_finite_vec(h->normal));
    if (!ordinary) return;
    FUZZ_CHECK(fg_unit_or_zero(h->normal, ntol, 0));
    FUZZ_CHECK(fabs((double)o.x + (double)h->fraction * (double)t.x - (double)h->point.x) <= ptol);
    FUZZ_CHECK(fabs((double)o.y + (double)h->fraction * (double)t.y - (double)h->point.y) <= ptol);
}

static void fg_queries(fz_reader *r, const fg_side *A, const fg_side *B)
{
    const ga2d_geometry *a = A->g;
    ga2d_vec o, t;
    ga2d_shape_proxy pa, pb;
    ga2d_simplex_cache cache;
    ga2d_distance_result d1, d2;
    ga2d_ray_result h, typed;
    ga2d_result res;
    double S, ptol, dtol, ntol;
    unsigned wild = fz_u8(r);
    int ordinary, must, may;
    o.x = wild & 1 ? fz_real(r, 4) : fz_narrow((double)(int8_t)fz_u8(r) / 16);
    o.y = wild & 1 ? fz_real(r, 4) : fz_narrow((double)(int8_t)fz_u8(r) / 16);
    t.x = wild & 2 ? fz_real(r, 4) : fz_narrow((double)(int8_t)fz_u8(r) / 8);
    t.y = wild & 2 ? fz_real(r, 4) : fz_narrow((double)(int8_t)fz_u8(r) / 8);
    pa = ga2d_shape_proxy_of(a);
    pb = ga2d_shape_proxy_of(B->g);
    S = fg_norm1(A->x.p) + fg_norm1(B->x.p) + fg_norm1(o) + fg_norm1(t) + A->in->reach + B->in->reach;
    ordinary = !A->in->nf && !A->in->inv && !B->in->nf && !B->in->inv && fz_finite(S) && S < 1e6 && A->dq < 1e-6 &&
               B->dq < 1e-6 && fz_finite_vec(o) && fz_finite_vec(t);
    ptol = (64 * FZ_EPS + 4 * (A->dq + B->dq)) * S + 4 * FZ_TINY;
    /* |n|^2 off 1: a normal normalized (a few eps), a polygon's own
       normals accepted within the collider's tolerance, the rotor's */
    ntol = 16 * FZ_EPS + 2 * A->in->ndev + 2 * A->dq;

    /* rays: the typed form in the shape's frame, the placed form in the
       world's; the same bits when the placement is the identity */
    res = ga2d_ray_cast_shape(a, A->x, o, t, &h);
    fg_check_errs(res,
                  A->in->nf || A->in->inv || !fz_finite_vec(o) || !fz_finite_vec(t) ||
                      !fz_finite_vec(ga2d_vec_add(o, t)) || (t.x == 0 && t.y == 0) ||
                      fg_xf_bad(A->x, A->dq) == 2,
                  A->in->maybe || fg_xf_bad(A->x, A->dq) == 1);
    if (res == GA2D_OK) fg_check_ray_hit(&h, o, t, ntol, ptol, ordinary);
    FUZZ_CHECK(ga2d_ray_cast_shape(a, A->x, o, t, NULL) != GA2D_OK);
    switch (a->type) {
    case GA2D_SHAPE_CIRCLE: typed = ga2d_ray_cast_circle(&a->as.circle, o, t); break;
    case GA2D_SHAPE_CAPSULE: typed = ga2d_ray_cast_capsule(&a->as.capsule, o, t); break;
    case GA2D_SHAPE_POLYGON: typed = ga2d_ray_cast_polygon(&a->as.polygon, o, t); break;
    case GA2D_SHAPE_SEGMENT: typed = ga2d_ray_cast_segment(&a->as.segment, o, t, 0); break;
    case GA2D_SHAPE_CHAIN_SEGMENT: typed = ga2d_ray_cast_segment(&a->as.chain_segment.segment, o, t, 1); break;
    default: typed = ga2d_ray_cast_circle(NULL, o, t); break;
    }
    if (a->type < 0 || a->type >= GA2D_SHAPE_TYPE_COUNT) FUZZ_CHECK(!typed.hit);
    {
        ga2d_transform id = ga2d_transform_identity();
        ga2d_ray_result h0;
        if (ga2d_ray_cast_shape(a, id, o, t, &h0) == GA2D_OK) {
            FG_TRACE((stderr, "ray type %d o (%g %g) t (%g %g): placed hit %d f %.9g p (%.9g %.9g) n (%.9g %.9g); typed hit %d f %.9g p (%.9g %.9g) n (%.9g %.9g)\n",
                      (int)a->type, (double)o.x, (double)o.y, (double)t.x, (double)t.y, h0.hit, (double)h0.fraction, (double)h0.point.x,
                      (double)h0.point.y, (double)h0.normal.x, (double)h0.normal.y, typed.hit, (double)typed.fraction,
                      (double)typed.point.x, (double)typed.point.y, (double)typed.normal.x, (double)typed.normal.y));
            /* equal values (the identity's turn may make a -0 a +0) */
            FUZZ_CHECK(h0.hit == typed.hit && h0.fraction == typed.fraction && h0.point.x == typed.point.x &&
                       h0.point.y == typed.point.y && h0.normal.x == typed.normal.x && h0.normal.y == typed.normal.y);
        }
        else if (a->type != GA2D_SHAPE_CHAIN_SEGMENT) FUZZ_CHECK(!typed.hit); /* the typed form has no ghosts to refuse */
        fg_check_ray_hit(&typed, o, t, 16 * FZ_EPS + 2 * A->in->ndev, ptol, ordinary);
    }
    if (ordinary && res == GA2D_OK && h.hit &&
        fabs((double)h.normal.x * (double)t.x + (double)h.normal.y * (double)t.y) > 1e-6 * fg_len(fg_d(t))) {
        /* the hit point is on the shape: within the rounding of it (unless
           the ray runs along the surface within rounding, where where it
           meets it is ill-conditioned: a segment tilted by 1e-313 rad) */
        ga2d_shape_proxy pt = ga2d_make_proxy(&h.point, 1, 0);
        ga2d_distance_result dp;
        /* a polygon's faces are its normals' half-planes, which the collider
           takes within FG_UNIT_TOL of its edges' (tilted by up to that), and
           GJK's are its vertices' hull: they part by up to that times its
           reach */
        double ftol = ptol + (a->type == GA2D_SHAPE_POLYGON ? 4 * FG_UNIT_TOL * (A->in->reach + fg_norm1(A->x.p)) : 0);
        if (ga2d_shape_distance(&pa, A->x, &pt, ga2d_transform_identity(), NULL, &dp) == GA2D_OK) {
            FG_TRACE((stderr, "hit point off the shape by %.9g (bound %.9g)\n", (double)dp.distance, ftol));
            FUZZ_CHECK((double)dp.distance <= ftol);
        }
    }

    /* distance, with a cache: zeroed, then reused (warm), then garbage */
    pa = fg_proxy(r, a);
    pb = fg_proxy(r, B->g);
    S = fg_norm1(A->x.p) + fg_norm1(B->x.p) + fg_proxy_reach(&pa) + fg_proxy_reach(&pb);
    ordinary = ordinary && fg_finite_proxy(&pa) && fg_finite_proxy(&pb) && fz_finite(S) && S < 1e6;
    dtol = (64 * FZ_EPS + 4 * (A->dq + B->dq)) * S + 4 * FZ_TINY;
    must = fg_proxy_errs(&pa) || fg_proxy_errs(&pb) || fg_xf_bad(A->x, A->dq) == 2 || fg_xf_bad(B->x, B->dq) == 2;
    may = fg_xf_bad(A->x, A->dq) == 1 || fg_xf_bad(B->x, B->dq) == 1;
    memset(&cache, 0, sizeof cache);
    res = ga2d_shape_distance(&pa, A->x, &pb, B->x, &cache, &d1);
    fg_check_errs(res, must, may);
    FUZZ_CHECK(ga2d_shape_distance(&pa, A->x, &pb, B->x, &cache, NULL) != GA2D_OK);
    FUZZ_CHECK(ga2d_shape_distance(NULL, A->x, &pb, B->x, &cache, &d2) == GA2D_ERR_INVALID_ARGUMENT);
    if (res == GA2D_OK) {
        FUZZ_CHECK(d1.iterations >= 0 && d1.iterations <= GA2D_GJK_MAX_ITERATIONS);
        FUZZ_CHECK(cache.count >= 0 && cache.count <= 3);
        FUZZ_CHECK(!(d1.distance < 0));
        FG_TRACE((stderr, "distance: a count %d r %g, b count %d r %g: d %.9g a (%.9g %.9g) b (%.9g %.9g) n (%.9g %.9g) it %d\n",
                  pa.count, (double)pa.radius, pb.count, (double)pb.radius, (double)d1.distance, (double)d1.point_a.x,
                  (double)d1.point_a.y, (double)d1.point_b.x, (double)d1.point_b.y, (double)d1.normal.x, (double)d1.normal.y,
                  d1.iterations));
#ifdef FUZZ_VERBOSE
        {
            int q;
            for (q = 0; q < pa.count; ++q) fprintf(stderr, "  a[%d] = (%a, %a)\n", q, (double)pa.points[q].x, (double)pa.points[q].y);
            for (q = 0; q < pb.count; ++q) fprintf(stderr, "  b[%d] = (%a, %a)\n", q, (double)pb.points[q].x, (double)pb.points[q].y);
            fprintf(stderr, "  xa (%a %a | %a %a) xb (%a %a | %a %a)\n", (double)A->x.p.x, (double)A->x.p.y, (double)A->x.q.c,
                    (double)A->x.q.s, (double)B->x.p.x, (double)B->x.p.y, (double)B->x.q.c, (double)B->x.q.s);
        }
#endif
        if (ordinary) {
            double gap = fg_len(fg_sub(fg_d(d1.point_b), fg_d(d1.point_a)));
            FUZZ_CHECK(fz_finite((double)d1.distance) && fz_finite_vec(d1.point_a) && fz_finite_vec(d1.point_b));
            FUZZ_CHECK(fg_unit_or_zero(d1.normal, 16 * FZ_EPS + 2 * A->dq, d1.distance == 0));
            /* the two points are the distance apart (both on the surfaces) */
            if (d1.distance > 0) FUZZ_CHECK(fabs(gap - (double)d1.distance) <= 2 * dtol);
            else FUZZ_CHECK(gap <= 2 * dtol);
        }
        /* warm: the same pair from the cache it left */
        FUZZ_CHECK(ga2d_shape_distance(&pa, A->x, &pb, B->x, &cache, &d2) == GA2D_OK);
        FUZZ_CHECK(d2.iterations >= 0 && d2.iterations <= GA2D_GJK_MAX_ITERATIONS);
        /* GJK stops within a relative tolerance of the distance (its
           progress test), from either start: the two answers agree to the
           rounding of the placement and that test */
        if (ordinary) FUZZ_CHECK(fabs((double)d2.distance - (double)d1.distance) <= 4 * dtol + 1e-3 * (double)d1.distance + FG_GJK_FLOOR);
        /* garbage: any count and indices are taken or dropped, never read past */
        cache.count = (int)fz_u8(r) - 8;
        cache.index_a[0] = (uint8_t)fz_u8(r);
        cache.index_b[0] = (uint8_t)fz_u8(r);
        cache.index_a[1] = cache.index_a[2] = (uint8_t)fz_u8(r);
        cache.index_b[1] = cache.index_b[2] = (uint8_t)fz_u8(r);
        FUZZ_CHECK(ga2d_shape_distance(&pa, A->x, &pb, B->x, &cache, &d2) == GA2D_OK);
        FG_TRACE((stderr, "garbage cache: d %.9g (was %.9g) it %d\n", (double)d2.distance, (double)d1.distance, d2.iterations));
        if (ordinary) FUZZ_CHECK(fabs((double)d2.distance - (double)d1.distance) <= 4 * dtol + 1e-3 * (double)d1.distance + FG_GJK_FLOOR);
        /* swapped: the same distance */
        FUZZ_CHECK(ga2d_shape_distance(&pb, B->x, &pa, A->x, NULL, &d2) == GA2D_OK);
        FG_TRACE((stderr, "swapped: d %.9g a (%.9g %.9g) b (%.9g %.9g) it %d\n", (double)d2.distance, (double)d2.point_a.x,
                  (double)d2.point_a.y, (double)d2.point_b.x, (double)d2.point_b.y, d2.iterations));
        if (ordinary) FUZZ_CHECK(fabs((double)d2.distance - (double)d1.distance) <= 4 * dtol + 1e-3 * (double)d1.distance + FG_GJK_FLOOR);
    }

    /* shape cast: B moved by t against A */
    res = ga2d_shape_cast(&pa, A->x, &pb, B->x, t, &h);
    fg_check_errs(res, must || !fz_finite_vec(t), may);
    if (res == GA2D_OK && h.hit) {
        FG_TRACE((stderr, "cast: t (%.9g %.9g): f %.9g p (%.9g %.9g) n (%.9g %.9g)\n", (double)t.x, (double)t.y, (double)h.fraction,
                  (double)h.point.x, (double)h.point.y, (double)h.normal.x, (double)h.normal.y));
        FUZZ_CHECK(h.fraction >= 0 && h.fraction <= 1);
        if (ordinary) {
            FUZZ_CHECK(fz_finite_vec(h.point));
            FUZZ_CHECK(fg_unit_or_zero(h.normal, 16 * FZ_EPS + 2 * A->dq, h.fraction == 0));
        }
    }

    /* time of impact: each proxy on a sweep (ordinary motion, or any) */
    {
        ga2d_sweep sa, sb;
        ga2d_toi_result toi;
        ga2d_real target, tmax;
        unsigned mode = fz_u8(r);
        int wild_sweep = mode >= 224, i;
        double slop = FG_SLOP;
        sa.local_center = wild_sweep ? ga2d_vec_make(fz_real(r, 1), fz_real(r, 1)) : ga2d_vec_make(0, 0);
        sb.local_center = wild_sweep ? ga2d_vec_make(fz_real(r, 1), fz_real(r, 1)) : ga2d_vec_make(0, 0);
        sa.c1 = A->x.p;
        sb.c1 = B->x.p;
        sa.c2 = ga2d_vec_add(A->x.p, wild_sweep ? ga2d_vec_make(fz_real(r, 4), fz_real(r, 4)) : ga2d_vec_make(0, 0));
        sb.c2 = ga2d_vec_add(B->x.p, t);
        sa.a1 = fz_narrow(atan2((double)A->x.q.s, (double)A->x.q.c));
        sb.a1 = fz_narrow(atan2((double)B->x.q.s, (double)B->x.q.c));
        sa.a2 = sa.a1 + (wild_sweep ? fz_real(r, 4) : fz_narrow((double)(int8_t)fz_u8(r) / 32));
        sb.a2 = sb.a1 + (wild_sweep ? fz_real(r, 4) : fz_narrow((double)(int8_t)fz_u8(r) / 32));
        target = (mode & 3) == 3 ? fz_real(r, 0.1) : (ga2d_real)GA2D_LINEAR_SLOP;
        tmax = (mode & 12) == 12 ? fz_real(r, 1) : 1;
        res = ga2d_time_of_impact(&pa, &sa, &pb, &sb, target, tmax, &toi);
        FUZZ_CHECK((int)res >= 0 && res < GA2D_RESULT_COUNT);
        if (fg_proxy_errs(&pa) || fg_proxy_errs(&pb) || !fz_finite((double)target) || !fz_finite((double)tmax) || target < 0 ||
            !(tmax > 0) || tmax > 1)
            FUZZ_CHECK(res != GA2D_OK);
        FUZZ_CHECK(ga2d_time_of_impact(&pa, &sa, &pb, NULL, target, tmax, &toi) != GA2D_OK);
        if (res != GA2D_OK) return;
        FUZZ_CHECK(res == GA2D_OK);
        FUZZ_CHECK(toi.state >= GA2D_TOI_SEPARATED && toi.state <= GA2D_TOI_GAVE_UP);
        FUZZ_CHECK(toi.iterations >= 0 && toi.iterations <= GA2D_TOI_MAX_ITERATIONS);
        FUZZ_CHECK(toi.t >= 0 && toi.t <= tmax);
        if (toi.state == GA2D_TOI_SEPARATED) FUZZ_CHECK(toi.t == tmax);
        if (toi.state == GA2D_TOI_OVERLAPPED) FUZZ_CHECK(toi.t == 0);
        if (!ordinary || wild_sweep || !fg_finite_proxy(&pa) || target > 1) return;
        /* never past an impact: sampled over [0, t], the proxies stay
           apart by the target less the stop tolerance (slop / 4) less the
           rounding of the placements (the sweep's S grows by t) */
        for (i = 0; i <= 16 && toi.state != GA2D_TOI_OVERLAPPED; ++i) {
            ga2d_real ti = fz_narrow((double)toi.t * i / 16);
            ga2d_distance_result di;
            if (ga2d_shape_distance(&pa, ga2d_sweep_transform(&sa, ti), &pb, ga2d_sweep_transform(&sb, ti), NULL, &di) != GA2D_OK)
                continue; /* a turned rotor within rounding of the tolerance */
            FUZZ_CHECK((double)di.distance >= (double)target - slop / 4 - 4 * dtol - 64 * FZ_EPS * fg_norm1(t));
        }
        if (toi.state == GA2D_TOI_HIT) {
            ga2d_distance_result di;
            if (ga2d_shape_distance(&pa, ga2d_sweep_transform(&sa, toi.t), &pb, ga2d_sweep_transform(&sb, toi.t), NULL, &di) ==
                GA2D_OK)
                FUZZ_CHECK((double)di.distance <= (double)target + slop / 4 + 4 * dtol + 64 * FZ_EPS * fg_norm1(t));
        }
    }
}

/* ------------------------------------------------------------ one input */
static int fuzz_shapes_one(const uint8_t *data, size_t size)
{
    fz_reader rd;
    ga2d_geometry a, b;
    fg_info ia, ib;
    fg_side A, B;
    ga2d_real units;
    unsigned flags;
    fz_init(&rd, data, size);
    flags = fz_u8(&rd);
    fg_geometry(&rd, &a);
    fg_geometry(&rd, &b);
    fg_classify(&a, &ia);
    fg_classify(&b, &ib);
    A.g = &a;
    A.in = &ia;
    B.g = &b;
    B.in = &ib;
    A.x = fg_transform(&rd, &A.dq);
    B.x = fg_transform(&rd, &B.dq);
    if (flags & 1) {
        /* both far from the origin, near each other: the collider
           subtracts the positions once */
        static const double offsets[6] = {1e3, -1e5, 1e6, 3e7, 1e12, -1e15};
        ga2d_vec o;
        o.x = fz_narrow(offsets[fz_pick(&rd, 6)]);
        o.y = fz_narrow(offsets[fz_pick(&rd, 6)]);
        A.x.p = ga2d_vec_add(A.x.p, o);
        B.x.p = ga2d_vec_add(B.x.p, o);
    }
    units = (flags & 6) != 6 ? 1 : fz_real_pos(&rd, 4);
    fg_collide(&A, &B, units);
    fg_masses(&rd, &a, &ia);
    fg_masses(&rd, &b, &ib);
    fg_makers(&rd);
    fg_queries(&rd, &A, &B);
    {
        /* bad arguments answered, not crashed on */
        ga2d_manifold m, sentinel;
        ga2d_mass ms;
        memset(&sentinel, 0x3C, sizeof sentinel);
        m = sentinel;
        FUZZ_CHECK(ga2d_collide_shapes(NULL, A.x, &b, B.x, &m) == -(int)GA2D_ERR_INVALID_ARGUMENT);
        FUZZ_CHECK(ga2d_collide_shapes(&a, A.x, NULL, B.x, &m) == -(int)GA2D_ERR_INVALID_ARGUMENT);
        FUZZ_CHECK(ga2d_collide_shapes(&a, A.x, &b, B.x, NULL) == -(int)GA2D_ERR_INVALID_ARGUMENT);
        FUZZ_CHECK(memcmp(&m, &sentinel, sizeof m) == 0);
        FUZZ_CHECK(ga2d_circle_mass_checked(NULL, 1, &ms) == GA2D_ERR_INVALID_ARGUMENT);
        FUZZ_CHECK(ga2d_capsule_mass_checked(NULL, 1, &ms) == GA2D_ERR_INVALID_ARGUMENT);
        FUZZ_CHECK(ga2d_circle_mass_checked(&a.as.circle, 1, NULL) == GA2D_ERR_INVALID_ARGUMENT);
        FUZZ_CHECK(ga2d_capsule_mass_checked(&a.as.capsule, 1, NULL) == GA2D_ERR_INVALID_ARGUMENT);
        FUZZ_CHECK(ga2d_circle_mass(NULL, 1).mass == 0 && ga2d_capsule_mass(NULL, 1).mass == 0);
    }
    return 0;
}

#endif
