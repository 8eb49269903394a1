/* svg_shapes.h - svg_writer.h for worlds of any shapes: records a world
   through all of its debug-draw callbacks (polygons, rounded polygons,
   circles, capsules and segments) and writes the run as one animated SVG
   (SMIL, no script: it plays in any browser).  For the examples only: it
   is not part of the library.  Include it after ga2d_physics.h, in one
   file; it builds on svg_writer.h's helpers.

     svgs rec;
     svgs_init(&rec, dt, 2);                 // keep every 2nd step
     svgs_record(&rec, world);               // the state before the run
     for (i = 0; i < steps; ++i) {
         ga2d_world_step(world, dt);
         svgs_record(&rec, world);           // after every step
     }
     svgs_write(&rec, "build/scene.svg", "a caption");  // bytes, or -1
     svgs_free(&rec);

   What it keeps: each body's shapes once, in the body's own frame, as the
   body had them when it was first drawn, and per kept frame the body's
   transform and state colour (GA2D_COLOR_*).  Segments (chains, walls)
   come from the debug draw in world coordinates with no body: those of
   the first kept frame are drawn, still, as polylines (consecutive
   segments that meet are joined).
   What it writes: a static body drawn once; a moving body as a <g>
   whose translation and rotation are animated by <animateTransform> and
   whose fill changes (awake -> asleep) by a discrete <animate>; a circle
   with a line from its centre along the body's x axis, so that rolling
   shows; a capsule and a rounded polygon with their round ends and
   corners as arcs.  Keys that linear interpolation reproduces are
   dropped, as svg_writer.h does.  The view fits where the moving bodies
   went (all bodies and segments if none moved), with room above for the
   caption; or it is the world box given to svgs_view.
   Options, set after svgs_init: svgs_view; svgs_style, a fill of its own
   for one body (a sensor drawn see-through, say); rec.pixels, the
   picture's larger side (640); rec.color_fn, which may recolour a body
   frame by frame (a body inside a sensor, say). */
#ifndef SVG_SHAPES_H
#define SVG_SHAPES_H

#include "svg_writer.h"

typedef struct svgs_shape {
    ga2d_shape_type type;     /* GA2D_SHAPE_CIRCLE, _CAPSULE or _POLYGON */
    ga2d_vec c1, c2;          /* circle: c1; capsule: c1-c2; body frame */
    ga2d_real radius;         /* circle and capsule */
    ga2d_polygon polygon;     /* polygon, its radius included */
} svgs_shape;

typedef struct svgs_body {
    svgw_body base;           /* id, moving, first, last and the samples
                                 (base.polygon is not used) */
    int shape_count, shape_capacity;
    svgs_shape *shapes;
    int frame;                /* the kept frame its sample was last taken in */
} svgs_body;

typedef struct svgs_segment { ga2d_vec a, b; } svgs_segment;
typedef struct svgs_override { ga2d_body_id id; char fill[64]; } svgs_override;

typedef struct svgs {
    svgw base;                /* frame_dt, hold, every, calls, frames, failed */
    int body_count, body_capacity;
    svgs_body *bodies;
    int slot_capacity;
    int *by_slot;             /* body record of each world slot, or -1 */
    int segment_count, segment_capacity;
    svgs_segment *segments;
    int override_count;
    svgs_override overrides[16];
    int has_view;
    double view[4];           /* xmin, ymin, xmax, ymax (world) */
    int pixels;               /* the picture's larger side (640) */
    /* if set, the colour a body is drawn with in this frame, given its
       state colour (to mark bodies the example is watching) */
    uint32_t (*color_fn)(ga2d_body_id id, uint32_t color, void *context);
    void *color_context;
    const ga2d_world *world;
} svgs;

/* Keeps one frame in `every` of a world stepped by step_dt seconds. */
SVGW_FN void svgs_init(svgs *s, double step_dt, int every)
{
    memset(s, 0, sizeof *s);
    svgw_init(&s->base, step_dt, every);
    s->pixels = 640;
}

SVGW_FN void svgs_free(svgs *s)
{
    int i;
    for (i = 0; i < s->body_count; ++i) {
        free(s->bodies[i].base.samples);
        free(s->bodies[i].shapes);
    }
    free(s->bodies);
    free(s->by_slot);
    free(s->segments);
    memset(s, 0, sizeof *s);
}

/* The world box the SVG shows, instead of the fitted one. */
SVGW_FN void svgs_view(svgs *s, double xmin, double ymin, double xmax, double ymax)
{
    s->has_view = 1;
    s->view[0] = xmin;
    s->view[1] = ymin;
    s->view[2] = xmax;
    s->view[3] = ymax;
}

/* Draws body id in this colour ("#7fb2e5") at this opacity (0..1)
   instead of its state colour; for up to 16 bodies. */
SVGW_FN void svgs_style(svgs *s, ga2d_body_id id, const char *color, double opacity)
{
    if (s->override_count >= (int)(sizeof s->overrides / sizeof s->overrides[0])) return;
    s->overrides[s->override_count].id = id;
    snprintf(s->overrides[s->override_count].fill, sizeof s->overrides[0].fill, "%s\" fill-opacity=\"%.3g", color,
             opacity);
    ++s->override_count;
}

/* The record of body id, made when first seen (NULL if out of memory). */
static svgs_body *svgs__body_of(svgs *s, ga2d_body_id id)
{
    int slot = (int)id.index1 - 1, r;
    svgs_body *b;
    void *q;
    if (s->base.failed || slot < 0) return NULL;
    if (slot >= s->slot_capacity) {
        int old = s->slot_capacity;
        q = svgw__grow(s->by_slot, &s->slot_capacity, slot + 1, sizeof *s->by_slot);
        if (!q) { s->base.failed = 1; return NULL; }
        s->by_slot = (int *)q;
        while (old < s->slot_capacity) s->by_slot[old++] = -1;
    }
    r = s->by_slot[slot];
    if (r < 0 || s->bodies[r].base.id.generation != id.generation) { /* new, or its slot reused */
        q = svgw__grow(s->bodies, &s->body_capacity, s->body_count + 1, sizeof *s->bodies);
        if (!q) { s->base.failed = 1; return NULL; }
        s->bodies = (svgs_body *)q;
        r = s->body_count++;
        b = &s->bodies[r];
        memset(b, 0, sizeof *b);
        b->base.id = id;
        b->base.moving = ga2d_body_get_type(s->world, id) != GA2D_BODY_STATIC;
        b->base.first = s->base.frames;
        b->frame = -1;
        s->by_slot[slot] = r;
    }
    return &s->bodies[r];
}

/* One shape of body id drawn in this frame: its geometry is kept in the
   frame the body is first seen, and the body's transform and colour once
   a frame. */
static void svgs__shape(svgs *s, ga2d_body_id id, const svgs_shape *shape, uint32_t color)
{
    svgs_body *b = svgs__body_of(s, id);
    svgw_sample sample;
    ga2d_transform x;
    void *q;
    if (!b) return;
    if (b->base.first == s->base.frames) { /* its first frame: keep the shape */
        q = svgw__grow(b->shapes, &b->shape_capacity, b->shape_count + 1, sizeof *b->shapes);
        if (!q) { s->base.failed = 1; return; }
        b->shapes = (svgs_shape *)q;
        b->shapes[b->shape_count++] = *shape;
    }
    if (b->frame == s->base.frames) return; /* sampled already */
    if (s->color_fn) color = s->color_fn(id, color, s->color_context);
    b->frame = s->base.frames;
    b->base.last = s->base.frames;
    if (b->base.count > 0 && !b->base.moving) return;
    x = ga2d_body_transform(s->world, id);
    sample.x = (double)x.p.x;
    sample.y = (double)x.p.y;
    sample.deg = (double)ga2d_rotor_angle(x.q) * (180 / 3.14159265358979323846);
    if (b->base.count > 0) { /* unwrap, so that interpolation turns the short way */
        double prev = b->base.samples[b->base.count - 1].deg;
        sample.deg += 360 * floor((prev - sample.deg) / 360 + 0.5);
    }
    sample.color = color;
    q = svgw__grow(b->base.samples, &b->base.capacity, b->base.count + 1, sizeof *b->base.samples);
    if (!q) { s->base.failed = 1; return; }
    b->base.samples = (svgw_sample *)q;
    b->base.samples[b->base.count++] = sample;
}

/* The debug-draw callbacks: the round shapes come in world coordinates
   and go back into the body's frame. */
static void svgs__polygon(ga2d_body_id id, const ga2d_polygon *p, ga2d_transform x, uint32_t color, void *context)
{
    svgs_shape sh;
    (void)x;
    memset(&sh, 0, sizeof sh);
    sh.type = GA2D_SHAPE_POLYGON;
    sh.polygon = *p;
    svgs__shape((svgs *)context, id, &sh, color);
}

static void svgs__circle(ga2d_body_id id, ga2d_vec center, ga2d_real radius, ga2d_vec axis, uint32_t color,
                         void *context)
{
    svgs *s = (svgs *)context;
    svgs_shape sh;
    (void)axis; /* the body's x axis: the body's own rotation says the same */
    memset(&sh, 0, sizeof sh);
    sh.type = GA2D_SHAPE_CIRCLE;
    sh.c1 = ga2d_transform_apply_inv(ga2d_body_transform(s->world, id), center);
    sh.radius = radius;
    svgs__shape(s, id, &sh, color);
}

static void svgs__capsule(ga2d_body_id id, ga2d_vec c1, ga2d_vec c2, ga2d_real radius, uint32_t color, void *context)
{
    svgs *s = (svgs *)context;
    ga2d_transform x = ga2d_body_transform(s->world, id);
    svgs_shape sh;
    memset(&sh, 0, sizeof sh);
    sh.type = GA2D_SHAPE_CAPSULE;
    sh.c1 = ga2d_transform_apply_inv(x, c1);
    sh.c2 = ga2d_transform_apply_inv(x, c2);
    sh.radius = radius;
    svgs__shape(s, id, &sh, color);
}

static void svgs__segment(ga2d_vec a, ga2d_vec b, uint32_t color, void *context)
{
    svgs *s = (svgs *)context;
    void *q;
    (void)color;
    if (s->base.failed || s->base.frames > 0) return; /* the first frame's only */
    q = svgw__grow(s->segments, &s->segment_capacity, s->segment_count + 1, sizeof *s->segments);
    if (!q) { s->base.failed = 1; return; }
    s->segments = (svgs_segment *)q;
    s->segments[s->segment_count].a = a;
    s->segments[s->segment_count].b = b;
    ++s->segment_count;
}

/* Call after every step (and once before the first): keeps every
   `every`-th call as a frame. */
SVGW_FN void svgs_record(svgs *s, const ga2d_world *w)
{
    ga2d_debug_draw d = ga2d_default_debug_draw();
    if (s->base.calls++ % s->base.every != 0) return;
    d.polygon = svgs__polygon;
    d.circle = svgs__circle;
    d.capsule = svgs__capsule;
    d.segment = svgs__segment;
    d.draw_joints = 0; /* a joint's lines move: only the still segments are kept */
    d.context = s;
    s->world = w;
    if (ga2d_world_draw(w, &d) != GA2D_OK) s->base.failed = 1;
    s->world = NULL;
    ++s->base.frames;
}

/* ------------------------------------------------------------- writing */
static void svgs__xy(FILE *f, double x, double y, int decimals)
{
    svgw__num(f, x, decimals);
    fputc(',', f);
    svgw__num(f, y, decimals);
}

/* "A r r 0 0 sweep x,y": an arc of radius r to (x, y); sweep 1 turns
   counter-clockwise in the body's (y-up) frame. */
static void svgs__arc(FILE *f, double r, int sweep, double x, double y, int decimals)
{
    fputs(" A", f);
    svgw__num(f, r, decimals);
    fputc(',', f);
    svgw__num(f, r, decimals);
    fprintf(f, " 0 0 %d ", sweep);
    svgs__xy(f, x, y, decimals);
}

/* One shape in its body's frame. */
static void svgs__shape_path(FILE *f, const svgs_shape *sh, int decimals)
{
    int i;
    if (sh->type == GA2D_SHAPE_CIRCLE) {
        double cx = (double)sh->c1.x, cy = (double)sh->c1.y, r = (double)sh->radius;
        fputs("<circle cx=\"", f);
        svgw__num(f, cx, decimals);
        fputs("\" cy=\"", f);
        svgw__num(f, cy, decimals);
        fputs("\" r=\"", f);
        svgw__num(f, r, decimals);
        fputs("\"/><path fill=\"none\" d=\"M", f); /* the radius along the body's x axis */
        svgs__xy(f, cx, cy, decimals);
        fputs(" L", f);
        svgs__xy(f, cx + r, cy, decimals);
        fputs("\"/>\n", f);
    } else if (sh->type == GA2D_SHAPE_CAPSULE) {
        double ax = (double)sh->c1.x, ay = (double)sh->c1.y, bx = (double)sh->c2.x, by = (double)sh->c2.y;
        double r = (double)sh->radius, dx = bx - ax, dy = by - ay, len = sqrt(dx * dx + dy * dy);
        double nx = len > 0 ? -dy / len * r : 0, ny = len > 0 ? dx / len * r : r; /* left of c1 -> c2 */
        fputs("<path d=\"M", f); /* round the far end clockwise, from its left to its right */
        svgs__xy(f, ax + nx, ay + ny, decimals);
        fputs(" L", f);
        svgs__xy(f, bx + nx, by + ny, decimals);
        svgs__arc(f, r, 0, bx - nx, by - ny, decimals);
        fputs(" L", f);
        svgs__xy(f, ax - nx, ay - ny, decimals);
        svgs__arc(f, r, 0, ax + nx, ay + ny, decimals);
        fputs("Z\"/>\n", f);
    } else {
        const ga2d_polygon *p = &sh->polygon;
        double r = (double)p->radius;
        fputs("<path d=\"M", f);
        if (r <= 0) {
            for (i = 0; i < p->count; ++i) {
                fputc(' ', f);
                svgs__xy(f, (double)p->vertices[i].x, (double)p->vertices[i].y, decimals);
            }
        } else /* edge i pushed out by r along its normal, then the arc round vertex i + 1 */
            for (i = 0; i < p->count; ++i) {
                int j = (i + 1) % p->count;
                ga2d_vec n = p->normals[i], m = p->normals[j], a = p->vertices[i], b = p->vertices[j];
                if (i == 0) svgs__xy(f, (double)a.x + r * (double)n.x, (double)a.y + r * (double)n.y, decimals);
                fputs(" L", f);
                svgs__xy(f, (double)b.x + r * (double)n.x, (double)b.y + r * (double)n.y, decimals);
                svgs__arc(f, r, 1, (double)b.x + r * (double)m.x, (double)b.y + r * (double)m.y, decimals);
            }
        fputs("Z\"/>\n", f);
    }
}

/* The fill a body is drawn with: its override, else its state colour. */
static const char *svgs__override(const svgs *s, ga2d_body_id id)
{
    int i;
    for (i = 0; i < s->override_count; ++i)
        if (ga2d_body_id_equal(s->overrides[i].id, id)) return s->overrides[i].fill;
    return NULL;
}

/* One body: a <g> placed by its translation, holding a <g> turned by its
   rotation and filled with its state colour, animated where they change,
   around its shapes. */
static void svgs__body(FILE *f, const svgs *s, const svgs_body *sb, char *keep, double tol, int decimals, double dur)
{
    const svgw_body *b = &sb->base;
    const svgw_sample *s0 = &b->samples[0];
    const char *fill = svgs__override(s, b->id);
    int animated = s->base.frames > 1, i, runs = 1;
    int move = animated && !svgw__constant(b->samples, b->count, 0, 1, tol);
    int turn = animated && !svgw__constant(b->samples, b->count, 2, 2, 0.1);
    for (i = 1; i < b->count; ++i) runs += b->samples[i].color != b->samples[i - 1].color;
    if (fill) runs = 1;

    fputs("<g transform=\"translate(", f);
    svgs__xy(f, s0->x, s0->y, decimals);
    fputs(")\">", f);
    if (animated && (b->first > 0 || b->last < s->base.frames - 1)) { /* exists for part of the run */
        svgw__anim(f, "animate", "visibility", dur);
        fputs(" calcMode=\"discrete\" keyTimes=\"0", f);
        if (b->first > 0) { fputc(';', f); svgw__num(f, b->first * s->base.frame_dt / dur, 5); }
        if (b->last < s->base.frames - 1) { fputc(';', f); svgw__num(f, (b->last + 1) * s->base.frame_dt / dur, 5); }
        fprintf(f, "\" values=\"%s%s\"/>", b->first > 0 ? "hidden;visible" : "visible",
                b->last < s->base.frames - 1 ? ";hidden" : "");
    }
    fputc('\n', f);
    if (move) {
        svgw__simplify(b->samples, b->count, 0, 1, tol, keep);
        svgw__transform_anim(f, &s->base, b, keep, 0, 1, decimals, dur);
    }
    fputs("<g", f);
    if (turn || fabs(s0->deg) > 1e-3) {
        fputs(" transform=\"rotate(", f);
        svgw__num(f, s0->deg, 2);
        fputs(")\"", f);
    }
    fputs(" fill=\"", f);
    if (fill) fputs(fill, f);
    else svgw__color(f, s0->color);
    fputs("\">\n", f);
    if (turn) {
        svgw__simplify(b->samples, b->count, 2, 2, 0.1, keep);
        svgw__transform_anim(f, &s->base, b, keep, 2, 2, 2, dur);
    }
    if (animated && runs > 1) { /* the colour runs, each from its first frame */
        svgw__anim(f, "animate", "fill", dur);
        fputs(" calcMode=\"discrete\" keyTimes=\"0", f);
        for (i = 1; i < b->count; ++i)
            if (b->samples[i].color != b->samples[i - 1].color) {
                fputc(';', f);
                svgw__num(f, (b->first + i) * s->base.frame_dt / dur, 5);
            }
        fputs("\" values=\"", f);
        svgw__color(f, s0->color);
        for (i = 1; i < b->count; ++i)
            if (b->samples[i].color != b->samples[i - 1].color) {
                fputc(';', f);
                svgw__color(f, b->samples[i].color);
            }
        fputs("\"/>\n", f);
    }
    for (i = 0; i < sb->shape_count; ++i) svgs__shape_path(f, &sb->shapes[i], decimals);
    fputs("</g></g>\n", f);
}

/* Grows box[] (xmin, ymin, xmax, ymax) by the disc (x, y, r). */
static void svgs__extend(double box[4], int *found, double x, double y, double r)
{
    if (!*found || x - r < box[0]) box[0] = x - r;
    if (!*found || y - r < box[1]) box[1] = y - r;
    if (!*found || x + r > box[2]) box[2] = x + r;
    if (!*found || y + r > box[3]) box[3] = y + r;
    *found = 1;
}

/* The world box of the moving bodies over the run (all bodies and the
   segments if none moves).  Returns 0 when there is nothing to frame. */
static int svgs__bounds(const svgs *s, double box[4])
{
    int pass, i, k, j, v, found = 0;
    for (pass = 0; pass < 2 && !found; ++pass) {
        for (i = 0; i < s->body_count; ++i) {
            const svgs_body *b = &s->bodies[i];
            if (pass == 0 && !b->base.moving) continue;
            for (k = 0; k < b->base.count; ++k) {
                const svgw_sample *sm = &b->base.samples[k];
                double c = cos(sm->deg * (3.14159265358979323846 / 180)), sn = sin(sm->deg * (3.14159265358979323846 / 180));
                for (j = 0; j < b->shape_count; ++j) {
                    const svgs_shape *sh = &b->shapes[j];
                    ga2d_vec pts[GA2D_MAX_POLYGON_VERTICES];
                    int n;
                    double r;
                    if (sh->type == GA2D_SHAPE_POLYGON) {
                        n = sh->polygon.count;
                        for (v = 0; v < n; ++v) pts[v] = sh->polygon.vertices[v];
                        r = (double)sh->polygon.radius;
                    } else {
                        n = sh->type == GA2D_SHAPE_CAPSULE ? 2 : 1;
                        pts[0] = sh->c1;
                        pts[1] = sh->c2;
                        r = (double)sh->radius;
                    }
                    for (v = 0; v < n; ++v) {
                        double px = (double)pts[v].x, py = (double)pts[v].y;
                        svgs__extend(box, &found, sm->x + px * c - py * sn, sm->y + px * sn + py * c, r);
                    }
                }
            }
        }
        if (pass == 1)
            for (i = 0; i < s->segment_count; ++i) {
                svgs__extend(box, &found, (double)s->segments[i].a.x, (double)s->segments[i].a.y, 0);
                svgs__extend(box, &found, (double)s->segments[i].b.x, (double)s->segments[i].b.y, 0);
            }
    }
    return found;
}

/* Writes the SVG.  Returns its size in bytes, or -1 (nothing recorded,
   out of memory, or the file could not be written). */
SVGW_FN long svgs_write(const svgs *s, const char *path, const char *caption)
{
    double box[4], w, h, pad, size, tol, dur, run, fs;
    double vx, vy; /* the viewBox's top-left corner, in SVG (y-down) units */
    int i, pass, decimals, max_count = 1;
    long bytes;
    char *keep;
    FILE *f;
    if (s->base.failed || s->base.frames == 0) return -1;
    if (s->has_view) memcpy(box, s->view, sizeof box);
    else if (!svgs__bounds(s, box)) return -1;
    w = box[2] - box[0];
    h = box[3] - box[1];
    size = w > h ? w : h;
    if (size <= 0) size = 1;
    pad = s->has_view ? 0 : 0.08 * size;
    box[0] -= pad; box[1] -= pad; box[2] += pad; box[3] += pad;
    if (!s->has_view) box[3] += 0.08 * size; /* room for the caption */
    w = box[2] - box[0];
    h = box[3] - box[1];
    if (w < h / 3) { box[0] -= (h / 3 - w) / 2; w = h / 3; } /* no slivers */
    if (h < w / 3) { box[3] += (w / 3 - h) / 2; /* the extra height goes above, under the caption */ h = w / 3; }
    size = w > h ? w : h;
    tol = size / 20000;
    decimals = (int)ceil(-log10(tol));
    if (decimals < 0) decimals = 0;
    run = (s->base.frames - 1) * s->base.frame_dt;
    dur = run + (s->base.hold > 0 ? s->base.hold : 0);
    if (dur <= 0) dur = 1;
    vx = box[0];
    vy = -box[3];
    fs = 0.03 * size;

    for (i = 0; i < s->body_count; ++i)
        if (s->bodies[i].base.count > max_count) max_count = s->bodies[i].base.count;
    keep = (char *)malloc((size_t)max_count);
    f = keep ? fopen(path, "w") : NULL;
    if (!f) { free(keep); return -1; }

    fprintf(f, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
               "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" viewBox=\"",
            (int)(s->pixels * w / size + 0.5), (int)(s->pixels * h / size + 0.5));
    svgw__num(f, vx, decimals); fputc(' ', f);
    svgw__num(f, vy, decimals); fputc(' ', f);
    svgw__num(f, w, decimals); fputc(' ', f);
    svgw__num(f, h, decimals);
    fputs("\">\n<title>", f);
    svgw__text(f, caption);
    fputs("</title>\n<rect x=\"", f);
    svgw__num(f, vx, decimals); fputs("\" y=\"", f);
    svgw__num(f, vy, decimals); fputs("\" width=\"100%\" height=\"100%\" fill=\"#fbfbf8\"/>\n", f);

    /* the scene, y up: segments, static bodies, then the moving ones */
    fputs("<g transform=\"scale(1,-1)\" stroke=\"#333\" stroke-linejoin=\"round\" stroke-width=\"", f);
    svgw__num(f, 0.0015 * size, decimals);
    fputs("\">\n", f);
    if (s->segment_count > 0) {
        fputs("<path fill=\"none\" stroke=\"#4c7f4c\" stroke-linecap=\"round\" stroke-width=\"", f);
        svgw__num(f, 0.004 * size, decimals);
        fputs("\" d=\"", f);
        for (i = 0; i < s->segment_count; ++i) {
            const svgs_segment *g = &s->segments[i];
            int joined = i > 0 && g->a.x == s->segments[i - 1].b.x && g->a.y == s->segments[i - 1].b.y;
            if (!joined) {
                fputs(i > 0 ? " M" : "M", f);
                svgs__xy(f, (double)g->a.x, (double)g->a.y, decimals);
            }
            fputs(" L", f);
            svgs__xy(f, (double)g->b.x, (double)g->b.y, decimals);
        }
        fputs("\"/>\n", f);
    }
    for (pass = 0; pass < 2; ++pass)
        for (i = 0; i < s->body_count; ++i)
            if (s->bodies[i].base.moving == pass && s->bodies[i].shape_count > 0)
                svgs__body(f, s, &s->bodies[i], keep, tol, decimals, dur);
    fputs("</g>\n", f);

    /* caption, legend, and a bar that grows with the simulated time */
    fprintf(f, "<g font-family=\"sans-serif\" font-size=\"%.4g\" fill=\"#333\">\n", fs);
    fprintf(f, "<text x=\"%.6g\" y=\"%.6g\">", vx + fs, vy + 1.6 * fs);
    svgw__text(f, caption);
    fputs("</text>\n", f);
    fprintf(f, "<rect x=\"%.6g\" y=\"%.6g\" width=\"%.4g\" height=\"%.4g\" fill=\"#%06x\"/>"
               "<text x=\"%.6g\" y=\"%.6g\">awake</text>\n",
            vx + fs, vy + 2.2 * fs, 0.8 * fs, 0.8 * fs, (unsigned)GA2D_COLOR_AWAKE, vx + 2.1 * fs, vy + 2.9 * fs);
    fprintf(f, "<rect x=\"%.6g\" y=\"%.6g\" width=\"%.4g\" height=\"%.4g\" fill=\"#%06x\"/>"
               "<text x=\"%.6g\" y=\"%.6g\">asleep</text>\n",
            vx + 5.6 * fs, vy + 2.2 * fs, 0.8 * fs, 0.8 * fs, (unsigned)GA2D_COLOR_ASLEEP, vx + 6.7 * fs, vy + 2.9 * fs);
    if (s->base.frames > 1) {
        fprintf(f, "<rect x=\"%.6g\" y=\"%.6g\" width=\"0\" height=\"%.4g\" fill-opacity=\"0.5\">", vx,
                vy + h - 0.25 * fs, 0.25 * fs);
        svgw__anim(f, "animate", "width", dur);
        fputs(" keyTimes=\"0;", f);
        svgw__num(f, run / dur, 5);
        fputs(";1\" values=\"0;", f);
        svgw__num(f, w, decimals);
        fputc(';', f);
        svgw__num(f, w, decimals);
        fputs("\"/></rect>\n", f);
    }
    fputs("</g>\n</svg>\n", f);
    free(keep);
    bytes = ferror(f) ? -1 : ftell(f);
    if (fclose(f) != 0) bytes = -1;
    return bytes;
}

#endif /* SVG_SHAPES_H */
