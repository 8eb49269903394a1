/* The world and its bodies: defaults, ids with generations, refusal of bad
   input with the world left bit-identical, the allocator (counting and
   failing), static and kinematic bodies, locking inside the force
   callback, mass data, and forces cleared after each step.

   "Unchanged" is checked strictly: a snapshot of every live body's state as
   the getters report it (position, rotor, centre, velocity, angular
   velocity, mass data, type, user data, polygon) plus the world's counters,
   time and gravity, compared with memcmp before and after a refused call.
   State the getters cannot see (pending forces, substeps, integrator) is
   checked by a twin: the same scene built again without the refused calls
   must step to the same bits.

   Rounding model for the tolerances: eps = REAL_EPS; one rounding of a
   result of size X is <= eps/2 X, so k roundings on values <= X stay
   below k eps X / 2, and we allow k eps X. */
#include "test.h"

#include <stdlib.h>

#define PI 3.14159265358979323846
#define MAXV GA2D_MAX_POLYGON_VERTICES

static const double DT = 1.0 / 60.0;
static int g_tags[16];

static ga2d_real real_nan(void) { return (ga2d_real)NAN; }
static ga2d_real real_inf(void) { return (ga2d_real)INFINITY; }
static ga2d_vec vec(double x, double y) { return ga2d_vec_make((ga2d_real)x, (ga2d_real)y); }
static int vec_same(ga2d_vec a, ga2d_vec b) { return a.x == b.x && a.y == b.y; }
static int vec_finite(ga2d_vec v) { return v.x - v.x == 0 && v.y - v.y == 0; }
static int real_finite(ga2d_real x) { return x - x == 0; }
static double len2(double x, double y) { return sqrt(x * x + y * y); }

/* A 1 m box of the given type at (x, y). */
static ga2d_body_def def_of(ga2d_body_type type, double x, double y)
{
    ga2d_body_def d = ga2d_default_body_def();
    d.polygon = ga2d_polygon_box((ga2d_real)0.5, (ga2d_real)0.5);
    d.type = type;
    d.position = vec(x, y);
    return d;
}

static ga2d_world *world_with_gravity(double gx, double gy)
{
    ga2d_world_def d = ga2d_default_world_def();
    d.gravity = vec(gx, gy);
    return ga2d_world_create(&d);
}

/* ------------------------------------------------------------- snapshot */
typedef struct snapshot { unsigned char *data; size_t len, cap; } snapshot;

static void snap_put(snapshot *s, const void *p, size_t n)
{
    if (s->len + n > s->cap) {
        size_t cap = s->cap ? s->cap : 4096;
        unsigned char *q;
        while (cap < s->len + n) cap *= 2;
        q = (unsigned char *)realloc(s->data, cap);
        if (!q) abort();
        s->data = q;
        s->cap = cap;
    }
    memcpy(s->data + s->len, p, n);
    s->len += n;
}
#define SNAP(s, lvalue) snap_put((s), &(lvalue), sizeof(lvalue))

/* Everything the getters say about the world and the bodies `ids` (with
   with_world = 0: the bodies only). */
static void snap_take(snapshot *s, const ga2d_world *w, const ga2d_body_id *ids, int n, int with_world)
{
    int i;
    s->len = 0;
    if (with_world) {
        ga2d_world_counters c = ga2d_world_get_counters(w);
        double t = ga2d_world_time(w);
        ga2d_vec g = ga2d_world_gravity(w);
        SNAP(s, c.body_count);
        SNAP(s, c.moving_body_count);
        SNAP(s, c.integrated_bodies);
        SNAP(s, c.force_evaluations);
        SNAP(s, c.rotation_updates);
        SNAP(s, c.step_count);
        SNAP(s, t);
        SNAP(s, g);
    }
    for (i = 0; i < n; ++i) {
        ga2d_body_id id = ids[i];
        int valid = ga2d_body_is_valid(w, id), type = (int)ga2d_body_get_type(w, id);
        ga2d_vec p = ga2d_body_position(w, id), c = ga2d_body_center(w, id), v = ga2d_body_velocity(w, id);
        ga2d_rotor q = ga2d_body_rotor(w, id);
        ga2d_real om = ga2d_body_angular_velocity(w, id), ke = ga2d_body_kinetic_energy(w, id);
        ga2d_mass m = ga2d_body_mass_data(w, id);
        void *ud = ga2d_body_user_data(w, id);
        const ga2d_polygon *poly = ga2d_body_polygon(w, id);
        SNAP(s, valid);
        SNAP(s, type);
        SNAP(s, p);
        SNAP(s, q);
        SNAP(s, c);
        SNAP(s, v);
        SNAP(s, om);
        SNAP(s, m.mass);
        SNAP(s, m.center);
        SNAP(s, m.inertia);
        SNAP(s, ke);
        SNAP(s, ud);
        if (poly) {
            snap_put(s, &poly->count, sizeof poly->count);
            snap_put(s, poly->vertices, sizeof poly->vertices);
            snap_put(s, poly->normals, sizeof poly->normals);
        }
    }
}

static int snap_same(const snapshot *a, const snapshot *b)
{
    return a->len == b->len && memcmp(a->data, b->data, a->len) == 0;
}

static void snap_free(snapshot *s)
{
    free(s->data);
    s->data = NULL;
    s->len = s->cap = 0;
}

/* ------------------------------------------------------------- fixture */
/* A world with one body of each kind, a step taken (counters and time not
   zero) and a force and torque pending, so a refused call that clears or
   adds to them shows in the twin comparison. */
typedef struct fixture {
    ga2d_world *w;
    ga2d_body_id ids[8];
    int n;
    ga2d_body_id dyn, kin, stat, fixed, tri;
    snapshot before, after;
} fixture;

static ga2d_body_id fixture_add(fixture *fx, const ga2d_body_def *d)
{
    ga2d_body_id id = ga2d_body_create(fx->w, d);
    CHECK(!ga2d_body_id_is_null(id));
    fx->ids[fx->n++] = id;
    return id;
}

static void fixture_make(fixture *fx)
{
    const ga2d_vec tri[3] = {{0, 0}, {2, 0}, {0, 1}};
    ga2d_body_def d;
    memset(fx, 0, sizeof *fx);
    fx->w = ga2d_world_create(NULL);
    CHECK(fx->w != NULL);
    if (!fx->w) return;

    d = def_of(GA2D_BODY_DYNAMIC, 1, 2);
    d.rotor = ga2d_rotor_from_angle((ga2d_real)0.3);
    d.velocity = vec(0.5, -1);
    d.angular_velocity = (ga2d_real)0.7;
    d.user_data = &g_tags[0];
    fx->dyn = fixture_add(fx, &d);

    d = def_of(GA2D_BODY_KINEMATIC, -3, 1);
    d.velocity = vec(1, 0);
    d.angular_velocity = (ga2d_real)-0.4;
    d.user_data = &g_tags[1];
    fx->kin = fixture_add(fx, &d);

    d = def_of(GA2D_BODY_STATIC, 0, -5);
    d.polygon = ga2d_polygon_box(10, (ga2d_real)0.5);
    d.user_data = &g_tags[2];
    fx->stat = fixture_add(fx, &d);

    d = def_of(GA2D_BODY_DYNAMIC, 4, 4);
    d.fixed_rotation = 1;
    d.velocity = vec(-1, 0.25);
    d.user_data = &g_tags[3];
    fx->fixed = fixture_add(fx, &d);

    d = def_of(GA2D_BODY_DYNAMIC, -2, -2);
    CHECK_RESULT(ga2d_polygon_make(tri, 3, &d.polygon), GA2D_OK);
    d.rotor = ga2d_rotor_from_angle(1);
    d.velocity = vec(0, 1);
    d.angular_velocity = -1;
    d.linear_damping = (ga2d_real)0.1;
    d.angular_damping = (ga2d_real)0.2;
    d.gravity_scale = (ga2d_real)0.5;
    d.restitution = (ga2d_real)0.3;
    d.user_data = &g_tags[4];
    fx->tri = fixture_add(fx, &d);

    CHECK_RESULT(ga2d_world_step(fx->w, (ga2d_real)DT), GA2D_OK);
    CHECK_RESULT(ga2d_body_apply_force(fx->w, fx->dyn, vec(1, 2), vec(1.5, 2.5)), GA2D_OK);
    CHECK_RESULT(ga2d_body_apply_torque(fx->w, fx->tri, (ga2d_real)0.5), GA2D_OK);
}

/* Steps the fixture next to a twin that saw none of the refused calls:
   both must reach the same bits.  Then frees both. */
static void fixture_finish(fixture *fx)
{
    fixture twin;
    int k;
    fixture_make(&twin);
    if (fx->w && twin.w) {
        for (k = 0; k < 3; ++k) {
            CHECK_RESULT(ga2d_world_step(fx->w, (ga2d_real)DT), GA2D_OK);
            CHECK_RESULT(ga2d_world_step(twin.w, (ga2d_real)DT), GA2D_OK);
        }
        snap_take(&fx->before, fx->w, fx->ids, fx->n, 1);
        snap_take(&twin.before, twin.w, twin.ids, twin.n, 1);
        if (!snap_same(&fx->before, &twin.before))
            test_fail(__FILE__, __LINE__, "a refused call changed hidden state: the twin steps differently");
    }
    ga2d_world_destroy(fx->w);
    ga2d_world_destroy(twin.w);
    snap_free(&fx->before);
    snap_free(&fx->after);
    snap_free(&twin.before);
    snap_free(&twin.after);
}

/* A refused call: the expected error and not one bit of the world changed. */
#define EXPECT_REFUSED(fx, call, expected)                                        \
    do {                                                                          \
        snap_take(&(fx)->before, (fx)->w, (fx)->ids, (fx)->n, 1);                 \
        CHECK_RESULT(call, expected);                                             \
        snap_take(&(fx)->after, (fx)->w, (fx)->ids, (fx)->n, 1);                  \
        if (!snap_same(&(fx)->before, &(fx)->after))                              \
            test_fail(__FILE__, __LINE__, "refused %s changed the world", #call); \
    } while (0)

/* A refused body creation: the null id, and not one bit changed. */
#define EXPECT_NULL_ID(fx, def_ptr)                                                 \
    do {                                                                            \
        snap_take(&(fx)->before, (fx)->w, (fx)->ids, (fx)->n, 1);                   \
        CHECK(ga2d_body_id_is_null(ga2d_body_create((fx)->w, def_ptr)));            \
        snap_take(&(fx)->after, (fx)->w, (fx)->ids, (fx)->n, 1);                    \
        if (!snap_same(&(fx)->before, &(fx)->after))                                \
            test_fail(__FILE__, __LINE__, "refused body_create changed the world"); \
    } while (0)

/* ------------------------------------------------------------ allocator */
#define ALLOC_MAGIC 0x6a2d7711u
#define MAX_BLOCKS 64

typedef struct alloc_block { void *p; size_t size; } alloc_block;

/* Counts every allocation, tracks each live block's size (so free must
   receive the size that was allocated), and can fail the fail_at-th
   allocation attempt (1-based; 0 = never). */
typedef struct counting_alloc {
    unsigned magic;
    long attempts, allocs, frees, failures, fail_at;
    size_t live_bytes;
    int bad_free, overflow;
    alloc_block blocks[MAX_BLOCKS];
    int nblocks;
} counting_alloc;

static int g_bad_ctx;

static void *ca_alloc(size_t size, void *ctx)
{
    counting_alloc *a = (counting_alloc *)ctx;
    void *p;
    if (!a || a->magic != ALLOC_MAGIC) {
        g_bad_ctx = 1;
        return NULL;
    }
    ++a->attempts;
    if (a->attempts == a->fail_at) {
        ++a->failures;
        return NULL;
    }
    if (a->nblocks == MAX_BLOCKS) {
        a->overflow = 1;
        return NULL;
    }
    p = malloc(size ? size : 1);
    if (!p) return NULL;
    a->blocks[a->nblocks].p = p;
    a->blocks[a->nblocks].size = size;
    ++a->nblocks;
    ++a->allocs;
    a->live_bytes += size;
    return p;
}

static void ca_free(void *ptr, size_t size, void *ctx)
{
    counting_alloc *a = (counting_alloc *)ctx;
    int i;
    if (!a || a->magic != ALLOC_MAGIC) {
        g_bad_ctx = 1;
        return; /* leak rather than free what we cannot account for */
    }
    for (i = 0; i < a->nblocks; ++i)
        if (a->blocks[i].p == ptr) break;
    if (i == a->nblocks) {
        ++a->bad_free; /* not ours, or freed twice */
        return;
    }
    if (a->blocks[i].size != size) ++a->bad_free;
    a->live_bytes -= a->blocks[i].size;
    a->blocks[i] = a->blocks[--a->nblocks];
    ++a->frees;
    free(ptr);
}

static void ca_init(counting_alloc *a, long fail_at)
{
    memset(a, 0, sizeof *a);
    a->magic = ALLOC_MAGIC;
    a->fail_at = fail_at;
}

static ga2d_world_def ca_world_def(counting_alloc *a)
{
    ga2d_world_def d = ga2d_default_world_def();
    d.allocator.alloc = ca_alloc;
    d.allocator.free = ca_free;
    d.allocator.ctx = a;
    return d;
}

/* all memory returned, every free with the right size and context */
static void ca_check_clean(const counting_alloc *a)
{
    CHECK(a->live_bytes == 0);
    CHECK(a->nblocks == 0);
    CHECK(a->allocs == a->frees);
    CHECK(a->bad_free == 0);
    CHECK(a->overflow == 0);
    CHECK(g_bad_ctx == 0);
}

/* ============================================================== defaults */
static void defaults(void)
{
    ga2d_world_def wd = ga2d_default_world_def();
    ga2d_body_def bd = ga2d_default_body_def();
    ga2d_polygon box = ga2d_polygon_box((ga2d_real)0.5, (ga2d_real)0.5);

    CHECK(wd.gravity.x == 0 && wd.gravity.y == -10);
    CHECK(wd.substeps == 4);
    CHECK(wd.integrator == GA2D_INTEGRATOR_SYMPLECTIC_EULER);
    CHECK(wd.rotation_update == GA2D_ROTATION_EXACT);
    CHECK(wd.length_units_per_meter == 1);
    CHECK(wd.allocator.alloc == NULL && wd.allocator.free == NULL && wd.allocator.ctx == NULL);
    CHECK(wd.force_callback == NULL && wd.force_context == NULL);
    CHECK_RESULT(ga2d_world_def_validate(&wd), GA2D_OK);

    CHECK(bd.type == GA2D_BODY_STATIC);
    CHECK(bd.position.x == 0 && bd.position.y == 0);
    CHECK(bd.rotor.c == 1 && bd.rotor.s == 0);
    CHECK(bd.velocity.x == 0 && bd.velocity.y == 0);
    CHECK(bd.angular_velocity == 0);
    /* no polygon: a body has no shape until it is given one */
    CHECK(bd.polygon.count == 0);
    CHECK(bd.density == 1);
    CHECK(bd.friction == (ga2d_real)0.6);
    CHECK(bd.restitution == 0);
    CHECK(bd.linear_damping == 0 && bd.angular_damping == 0);
    CHECK(bd.gravity_scale == 1);
    CHECK(bd.fixed_rotation == 0);
    CHECK(bd.is_awake == 1);
    CHECK(bd.user_data == NULL);
    CHECK_RESULT(ga2d_body_def_validate(&bd), GA2D_OK);

    /* the default body is static and has no shape; made dynamic it has
       mass 1 and no inertia until a shape gives it some (DESIGN 10); given
       the 1 m box, mass 1 and I = m (1 + 1) / 12 = 1/6 about its centre
       (0, 0): a few roundings of values <= 1, so 8 eps */
    {
        ga2d_world *w = ga2d_world_create(NULL);
        ga2d_body_id s, d;
        ga2d_mass m;
        CHECK(w != NULL);
        if (!w) return;
        s = ga2d_body_create(w, &bd);
        CHECK(!ga2d_body_id_is_null(s));
        CHECK(ga2d_body_get_type(w, s) == GA2D_BODY_STATIC);
        bd.type = GA2D_BODY_DYNAMIC;
        d = ga2d_body_create(w, &bd);
        CHECK(!ga2d_body_id_is_null(d));
        CHECK(ga2d_body_get_type(w, d) == GA2D_BODY_DYNAMIC);
        m = ga2d_body_mass_data(w, d);
        CHECK(m.mass == 1 && m.inertia == 0 && ga2d_body_get_shapes(w, d, NULL, 0) == 0);
        bd.polygon = box;
        d = ga2d_body_create(w, &bd);
        m = ga2d_body_mass_data(w, d);
        CHECK(ga2d_body_get_shapes(w, d, NULL, 0) == 1);
        CHECK_NEAR(m.mass, 1, 8 * REAL_EPS);
        CHECK_NEAR(m.inertia, 1.0 / 6.0, 8 * REAL_EPS);
        CHECK_NEAR(m.center.x, 0, 8 * REAL_EPS);
        CHECK_NEAR(m.center.y, 0, 8 * REAL_EPS);
        ga2d_world_destroy(w);
    }
}

/* A box on a 20 degree slope with friction 0.6 (tan 20 = 0.364 < 0.6:
   static friction holds it), in a world made from `wd`; returns how far
   the box's centre moved in 2 s and whether it is asleep, and fills
   `state` with its centre, rotor and velocities for a bitwise comparison. */
static double slope_slide(const ga2d_world_def *wd, const ga2d_body_def *box_template, ga2d_real state[7], int *asleep)
{
    const double theta = 20 * PI / 180;
    ga2d_world *w = ga2d_world_create(wd);
    ga2d_body_def g = ga2d_default_body_def(), b = *box_template;
    ga2d_body_id id;
    ga2d_vec c0, c1;
    int i;
    if (!w) return -1;
    g.polygon = ga2d_polygon_box(10, (ga2d_real)0.5);
    g.rotor = ga2d_rotor_from_angle((ga2d_real)theta);
    /* the slope's top face passes through the origin */
    g.position = vec(0.5 * sin(theta), -0.5 * cos(theta));
    CHECK(!ga2d_body_id_is_null(ga2d_body_create(w, &g)));
    b.type = GA2D_BODY_DYNAMIC;
    b.rotor = g.rotor;
    b.position = vec(-0.5 * sin(theta), 0.5 * cos(theta)); /* resting on the face */
    id = ga2d_body_create(w, &b);
    CHECK(!ga2d_body_id_is_null(id));
    c0 = ga2d_body_center(w, id);
    for (i = 0; i < 120; ++i) CHECK_RESULT(ga2d_world_step(w, (ga2d_real)DT), GA2D_OK);
    c1 = ga2d_body_center(w, id);
    state[0] = c1.x, state[1] = c1.y;
    state[2] = ga2d_body_rotor(w, id).c, state[3] = ga2d_body_rotor(w, id).s;
    state[4] = ga2d_body_velocity(w, id).x, state[5] = ga2d_body_velocity(w, id).y;
    state[6] = ga2d_body_angular_velocity(w, id);
    *asleep = !ga2d_body_is_awake(w, id);
    ga2d_world_destroy(w);
    return len2((double)c1.x - (double)c0.x, (double)c1.y - (double)c0.y);
}

/* A zero-initialised world def (plus gravity, or without it) is the
   default def: every zero field takes its default, the switches included
   (a zeroed def used to read enable_friction = 0 as off, and the box slid
   6.9 m in 2 s).  The box on the slope ends bit for bit where it ends in
   the default world, and it held: frictionless it would slide
   g sin(theta) t^2 / 2 = 6.84 m; held, it moves by no more than a linear
   slop (the soft contact settles it into the slope by at most that).  A
   switch set to 0 in a def from ga2d_default_world_def() is off: without
   friction the box slides as symplectic Euler's parabola has it,
   a t (t + h) / 2 with a = g sin(theta) and h = dt/4 the substep (each
   drift uses the velocity already kicked: 14 mm past the exact 6.84 m),
   within a slop (the contact presses the box into the slope by at most
   that, and the roundings are far smaller); and without sleep it stays
   awake. */
static void zero_world_def(void)
{
    const double a = 10 * sin(20 * PI / 180), slide = 0.5 * a * 2 * (2 + DT / 4);
    ga2d_world_def zero, dflt = ga2d_default_world_def(), off;
    ga2d_body_def box = ga2d_default_body_def();
    ga2d_real s0[7], s1[7], s2[7];
    int asleep0, asleep1, asleep2, i;
    double d0, d1, d2;
    memset(&zero, 0, sizeof zero);
    box.polygon = ga2d_polygon_box((ga2d_real)0.5, (ga2d_real)0.5);
    CHECK_RESULT(ga2d_world_def_validate(&zero), GA2D_OK);
    d0 = slope_slide(&dflt, &box, s0, &asleep0);
    d1 = slope_slide(&zero, &box, s1, &asleep1);
    for (i = 0; i < 7; ++i) CHECK(s0[i] == s1[i]);
    CHECK(asleep0 == asleep1);
    CHECK(d0 >= 0 && d0 <= GA2D_LINEAR_SLOP);
    CHECK(d1 == d0);
    /* the same with gravity set by hand */
    zero.gravity = vec(0, -10);
    d1 = slope_slide(&zero, &box, s1, &asleep1);
    for (i = 0; i < 7; ++i) CHECK(s0[i] == s1[i]);
    /* switches off, from the default def */
    off = dflt;
    off.enable_friction = 0;
    d2 = slope_slide(&off, &box, s2, &asleep2);
    CHECK(fabs(d2 - slide) <= GA2D_LINEAR_SLOP);
    off = dflt;
    off.enable_sleep = 0;
    slope_slide(&off, &box, s2, &asleep2);
    CHECK(asleep0 && !asleep2);
    if (getenv("GA2D_TEST_VERBOSE"))
        printf("  world: zeroed def: box moved %.3g m (default %.3g m, bound %.3g); friction off %.4f m "
               "(bounds %.4f..%.4f)\n",
               d1, d0, GA2D_LINEAR_SLOP, d2, slide - GA2D_LINEAR_SLOP, slide + GA2D_LINEAR_SLOP);
}

/* A zero-initialised body def is the default body def: a static body
   with no shape, density 1 and friction 0.6 for a polygon it may be given,
   awake.  Made dynamic without a shape it has mass 1 (DESIGN 10); given
   the 1 m box, the box's exact mass, 1 kg (density 1 times 1 m^2, one
   rounding).  A zero-density dynamic def from the default function is
   still refused, and says why. */
static void zero_body_def(void)
{
    ga2d_body_def zero, dflt = ga2d_default_body_def();
    ga2d_world *w = ga2d_world_create(NULL);
    ga2d_body_id a, b;
    int i;
    CHECK(w != NULL);
    if (!w) return;
    memset(&zero, 0, sizeof zero);
    CHECK_RESULT(ga2d_body_def_validate(&zero), GA2D_OK);
    a = ga2d_body_create(w, &zero);
    b = ga2d_body_create(w, &dflt);
    CHECK(!ga2d_body_id_is_null(a) && !ga2d_body_id_is_null(b));
    CHECK(ga2d_body_get_type(w, a) == GA2D_BODY_STATIC);
    CHECK(ga2d_body_polygon(w, a) == NULL && ga2d_body_polygon(w, b) == NULL);
    CHECK(ga2d_body_get_shapes(w, a, NULL, 0) == 0 && ga2d_body_get_shapes(w, b, NULL, 0) == 0);
    CHECK(ga2d_body_rotor(w, a).c == 1 && ga2d_body_rotor(w, a).s == 0);
    zero.type = GA2D_BODY_DYNAMIC;
    a = ga2d_body_create(w, &zero);
    CHECK(!ga2d_body_id_is_null(a));
    CHECK(ga2d_body_mass_data(w, a).mass == 1);
    zero.polygon = ga2d_polygon_box((ga2d_real)0.5, (ga2d_real)0.5);
    a = ga2d_body_create(w, &zero);
    CHECK(!ga2d_body_id_is_null(a));
    CHECK(ga2d_body_polygon(w, a) != NULL && ga2d_body_polygon(w, a)->count == 4);
    for (i = 0; i < 4 && ga2d_body_polygon(w, a); ++i)
        CHECK(vec_same(ga2d_body_polygon(w, a)->vertices[i], zero.polygon.vertices[i]));
    CHECK_NEAR(ga2d_body_mass_data(w, a).mass, 1, REAL_EPS);
    CHECK(ga2d_body_is_awake(w, a));
    dflt.type = GA2D_BODY_DYNAMIC;
    dflt.density = 0;
    CHECK_RESULT(ga2d_body_def_validate(&dflt), GA2D_ERR_INVALID_ARGUMENT);
    CHECK(ga2d_body_id_is_null(ga2d_body_create(w, &dflt)));
    CHECK(ga2d_world_get_counters(w).body_count == 4);
    ga2d_world_destroy(w);
}

/* ga2d_world_create(NULL) is the default world: gravity (0, -10), 4
   substeps.  A dynamic body falls by v = g dt after one step: four
   additions of g h, each exact-or-one-rounding of values <= 10 dt: 4 eps. */
static void create_null_def(void)
{
    ga2d_world *w = ga2d_world_create(NULL);
    ga2d_body_def bd = def_of(GA2D_BODY_DYNAMIC, 0, 0);
    ga2d_body_id id;
    ga2d_real dt = (ga2d_real)DT;
    CHECK(w != NULL);
    if (!w) return;
    CHECK(vec_same(ga2d_world_gravity(w), vec(0, -10)));
    id = ga2d_body_create(w, &bd);
    CHECK_RESULT(ga2d_world_step(w, dt), GA2D_OK);
    CHECK(ga2d_world_get_counters(w).integrated_bodies == 4);
    CHECK(ga2d_body_velocity(w, id).x == 0);
    CHECK_NEAR(ga2d_body_velocity(w, id).y, -10 * (double)dt, 4 * REAL_EPS * 10 * (double)dt);
    CHECK(ga2d_world_time(w) == (double)dt);
    ga2d_world_destroy(w);
}

/* =================================================================== ids */
/* Every getter answers a refused id with zero (identity for rotors). */
static void check_getters_refuse(const ga2d_world *w, ga2d_body_id id)
{
    ga2d_transform x = ga2d_body_transform(w, id);
    ga2d_mass m = ga2d_body_mass_data(w, id);
    CHECK(!ga2d_body_is_valid(w, id));
    CHECK(ga2d_body_get_type(w, id) == GA2D_BODY_STATIC);
    CHECK(vec_same(ga2d_body_position(w, id), vec(0, 0)));
    CHECK(ga2d_body_rotor(w, id).c == 1 && ga2d_body_rotor(w, id).s == 0);
    CHECK(ga2d_body_angle(w, id) == 0);
    CHECK(vec_same(x.p, vec(0, 0)) && x.q.c == 1 && x.q.s == 0);
    CHECK(vec_same(ga2d_body_center(w, id), vec(0, 0)));
    CHECK(vec_same(ga2d_body_velocity(w, id), vec(0, 0)));
    CHECK(ga2d_body_angular_velocity(w, id) == 0);
    CHECK(vec_same(ga2d_body_velocity_at(w, id, vec(3, 4)), vec(0, 0)));
    CHECK(m.mass == 0 && m.inertia == 0 && vec_same(m.center, vec(0, 0)));
    CHECK(ga2d_body_kinetic_energy(w, id) == 0);
    CHECK(ga2d_body_polygon(w, id) == NULL);
    CHECK(ga2d_body_user_data(w, id) == NULL);
}

/* Every setter and apply_* answers a refused id with STALE_ID (given
   arguments that would otherwise be accepted). */
static void check_setters_refuse(ga2d_world *w, ga2d_body_id id)
{
    ga2d_mass m;
    m.mass = 2;
    m.center = vec(0.1, 0);
    m.inertia = 1;
    CHECK_RESULT(ga2d_body_destroy(w, id), GA2D_ERR_STALE_ID);
    CHECK_RESULT(ga2d_body_set_transform(w, id, vec(1, 1), ga2d_rotor_identity()), GA2D_ERR_STALE_ID);
    CHECK_RESULT(ga2d_body_set_velocity(w, id, vec(1, 1)), GA2D_ERR_STALE_ID);
    CHECK_RESULT(ga2d_body_set_angular_velocity(w, id, 1), GA2D_ERR_STALE_ID);
    CHECK_RESULT(ga2d_body_set_mass_data(w, id, m), GA2D_ERR_STALE_ID);
    CHECK_RESULT(ga2d_body_set_gravity_scale(w, id, 2), GA2D_ERR_STALE_ID);
    CHECK_RESULT(ga2d_body_set_damping(w, id, 1, 1), GA2D_ERR_STALE_ID);
    CHECK_RESULT(ga2d_body_set_user_data(w, id, &g_tags[9]), GA2D_ERR_STALE_ID);
    CHECK_RESULT(ga2d_body_apply_force(w, id, vec(1, 0), vec(0, 0)), GA2D_ERR_STALE_ID);
    CHECK_RESULT(ga2d_body_apply_force_to_center(w, id, vec(1, 0)), GA2D_ERR_STALE_ID);
    CHECK_RESULT(ga2d_body_apply_torque(w, id, 1), GA2D_ERR_STALE_ID);
    CHECK_RESULT(ga2d_body_apply_impulse(w, id, vec(1, 0), vec(0, 0)), GA2D_ERR_STALE_ID);
    CHECK_RESULT(ga2d_body_apply_angular_impulse(w, id, 1), GA2D_ERR_STALE_ID);
}

static void check_refused(ga2d_world *w, ga2d_body_id id)
{
    check_getters_refuse(w, id);
    check_setters_refuse(w, id);
}

static void ids_and_generations(void)
{
    ga2d_world *w = ga2d_world_create(NULL);
    ga2d_body_def d = def_of(GA2D_BODY_DYNAMIC, 1, 1);
    ga2d_body_id null = ga2d_body_id_null(), a, b, c, live[2];
    snapshot before, after;
    test_rng rng;
    int i;
    memset(&before, 0, sizeof before);
    memset(&after, 0, sizeof after);
    CHECK(w != NULL);
    if (!w) return;

    /* the null id is the zero value */
    CHECK(null.index1 == 0 && null.generation == 0);
    CHECK(ga2d_body_id_is_null(null));
    CHECK(ga2d_body_id_equal(null, ga2d_body_id_null()));
    check_refused(w, null);

    d.user_data = &g_tags[5];
    a = ga2d_body_create(w, &d);
    d.position = vec(-1, 3);
    d.user_data = &g_tags[6];
    b = ga2d_body_create(w, &d);
    CHECK(!ga2d_body_id_is_null(a) && !ga2d_body_id_is_null(b));
    CHECK(ga2d_body_id_equal(a, a) && !ga2d_body_id_equal(a, b) && !ga2d_body_id_equal(a, null));
    CHECK(ga2d_body_is_valid(w, a) && ga2d_body_is_valid(w, b));
    CHECK(ga2d_world_get_counters(w).body_count == 2);
    CHECK(ga2d_body_user_data(w, a) == &g_tags[5] && ga2d_body_user_data(w, b) == &g_tags[6]);

    /* destroy a: refused everywhere, b untouched, twice is STALE_ID */
    snap_take(&before, w, &b, 1, 0);
    CHECK_RESULT(ga2d_body_destroy(w, a), GA2D_OK);
    CHECK(ga2d_world_get_counters(w).body_count == 1);
    CHECK(ga2d_world_get_counters(w).moving_body_count == 1);
    CHECK_RESULT(ga2d_body_destroy(w, a), GA2D_ERR_STALE_ID);
    check_refused(w, a);
    snap_take(&after, w, &b, 1, 0);
    CHECK(snap_same(&before, &after));

    /* a new body (probably in a's slot): a new id, a stays refused */
    d.position = vec(7, 7);
    d.user_data = &g_tags[7];
    c = ga2d_body_create(w, &d);
    CHECK(!ga2d_body_id_is_null(c));
    CHECK(!ga2d_body_id_equal(c, a) && !ga2d_body_id_equal(c, b));
    CHECK(ga2d_world_get_counters(w).body_count == 2);
    snap_take(&before, w, &c, 1, 0);
    check_refused(w, a);
    snap_take(&after, w, &c, 1, 0);
    CHECK(snap_same(&before, &after));
    CHECK(ga2d_body_user_data(w, c) == &g_tags[7]);
    CHECK_NEAR(ga2d_body_position(w, c).x, 7, 2 * 7 * REAL_EPS);

    /* forged ids: past the end, the largest index, random index and
       generation (skipping the rare draw that names a live body), and a
       guessed generation for a's slot */
    live[0] = b;
    live[1] = c;
    snap_take(&before, w, live, 2, 1);
    {
        ga2d_body_id f;
        f.index1 = 3;
        f.generation = 1;
        check_refused(w, f);
        f.index1 = 1000;
        check_refused(w, f);
        f.index1 = 0xFFFFFFFFu;
        f.generation = 0xFFFFFFFFu;
        check_refused(w, f);
        f.index1 = 0; /* a null id with a generation */
        f.generation = 5;
        CHECK(ga2d_body_id_is_null(f));
        check_refused(w, f);
        for (i = 0; i < 4; ++i) {
            f.index1 = a.index1;
            f.generation = a.generation + (uint32_t)i;
            if (ga2d_body_id_equal(f, c)) continue;
            check_refused(w, f);
        }
        rng.state = 99;
        for (i = 0; i < 2000; ++i) {
            f.index1 = (uint32_t)rng_next(&rng);
            f.generation = (uint32_t)rng_next(&rng);
            if (i % 2) f.index1 = f.index1 % 4; /* plausible small indices too */
            if (ga2d_body_id_equal(f, b) || ga2d_body_id_equal(f, c)) continue;
            check_getters_refuse(w, f);
            CHECK_RESULT(ga2d_body_set_velocity(w, f, vec(1, 1)), GA2D_ERR_STALE_ID);
            CHECK_RESULT(ga2d_body_destroy(w, f), GA2D_ERR_STALE_ID);
        }
    }
    snap_take(&after, w, live, 2, 1);
    CHECK(snap_same(&before, &after));

    /* destroy b: its slot is free, and any generation for it is refused */
    CHECK_RESULT(ga2d_body_destroy(w, b), GA2D_OK);
    CHECK(ga2d_world_get_counters(w).body_count == 1);
    {
        ga2d_body_id f = b;
        for (i = 0; i < 4; ++i, ++f.generation) check_refused(w, f);
    }
    CHECK_RESULT(ga2d_body_destroy(w, c), GA2D_OK);
    CHECK(ga2d_world_get_counters(w).body_count == 0);
    CHECK(ga2d_world_get_counters(w).moving_body_count == 0);
    check_refused(w, b);
    check_refused(w, c);
    snap_free(&before);
    snap_free(&after);
    ga2d_world_destroy(w);
}

/* 5000 bodies, every other one destroyed, 2500 new ones: survivors keep
   their own state, old ids stay refused, new ids are new, the freed slots
   are reused (no allocation while recreating), and one step moves each by
   its own velocity. */
#define MANY 5000
static void many_bodies(void)
{
    static ga2d_body_id ids[MANY], fresh[MANY / 2];
    static int tags[MANY], fresh_tags[MANY / 2];
    counting_alloc ca;
    ga2d_world_def wd;
    ga2d_world *w;
    ga2d_real dt = (ga2d_real)DT;
    long allocs_before;
    int i, j;
    ca_init(&ca, 0);
    wd = ca_world_def(&ca);
    wd.gravity = vec(0, 0);
    w = ga2d_world_create(&wd);
    CHECK(w != NULL);
    if (!w) return;
    for (i = 0; i < MANY; ++i) {
        ga2d_body_def d = def_of(GA2D_BODY_DYNAMIC, i, 0.5 * i);
        d.velocity = vec(i % 7 - 3, i % 5 - 2);
        d.user_data = &tags[i];
        ids[i] = ga2d_body_create(w, &d);
        CHECK(!ga2d_body_id_is_null(ids[i]));
    }
    CHECK(ga2d_world_get_counters(w).body_count == MANY);
    for (i = 0; i < MANY; i += 2) CHECK_RESULT(ga2d_body_destroy(w, ids[i]), GA2D_OK);
    CHECK(ga2d_world_get_counters(w).body_count == MANY / 2);
    CHECK(ga2d_world_get_counters(w).moving_body_count == MANY / 2);

    allocs_before = ca.allocs;
    for (j = 0; j < MANY / 2; ++j) {
        ga2d_body_def d = def_of(GA2D_BODY_DYNAMIC, -j, 3);
        d.velocity = vec(1, -1);
        d.user_data = &fresh_tags[j];
        fresh[j] = ga2d_body_create(w, &d);
        CHECK(!ga2d_body_id_is_null(fresh[j]));
    }
    CHECK(ca.allocs == allocs_before); /* the freed slots were reused */
    CHECK(ga2d_world_get_counters(w).body_count == MANY);
    for (i = 0; i < MANY; i += 2) {
        CHECK(!ga2d_body_is_valid(w, ids[i]));
        CHECK(ga2d_body_user_data(w, ids[i]) == NULL);
    }
    /* no new id equals a destroyed one, and each names its own body */
    {
        static ga2d_body_id by_index[MANY + 1];
        memset(by_index, 0, sizeof by_index);
        for (i = 0; i < MANY; i += 2)
            if (ids[i].index1 <= MANY) by_index[ids[i].index1] = ids[i];
        for (j = 0; j < MANY / 2; ++j)
            if (fresh[j].index1 <= MANY) CHECK(!ga2d_body_id_equal(fresh[j], by_index[fresh[j].index1]));
    }

    CHECK_RESULT(ga2d_world_step(w, dt), GA2D_OK);
    for (i = 1; i < MANY; i += 2) {
        /* after one step x = p + v dt: the origin went to the centre and
           back (p + c, then - c: 2 roundings) and 4 substep additions, on
           values <= |p| + |v| dt + 1: 8 eps (|p| + 4) */
        double vx = i % 7 - 3, vy = i % 5 - 2;
        double tol = 8 * REAL_EPS * (len2(i, 0.5 * i) + 4);
        ga2d_vec p = ga2d_body_position(w, ids[i]);
        CHECK(ga2d_body_user_data(w, ids[i]) == &tags[i]);
        CHECK(vec_same(ga2d_body_velocity(w, ids[i]), vec(vx, vy)));
        CHECK_NEAR(p.x, i + vx * (double)dt, tol);
        CHECK_NEAR(p.y, 0.5 * i + vy * (double)dt, tol);
    }
    for (j = 0; j < MANY / 2; ++j) {
        double tol = 8 * REAL_EPS * (j + 8);
        ga2d_vec p = ga2d_body_position(w, fresh[j]);
        CHECK(ga2d_body_user_data(w, fresh[j]) == &fresh_tags[j]);
        CHECK_NEAR(p.x, -j + (double)dt, tol);
        CHECK_NEAR(p.y, 3 - (double)dt, tol);
    }
    ga2d_world_destroy(w);
    ca_check_clean(&ca);
}

/* ============================================================= bad input */
/* Pointers to every real field of a body def. */
static int def_real_fields(ga2d_body_def *d, ga2d_real **f)
{
    int n = 0;
    f[n++] = &d->position.x;
    f[n++] = &d->position.y;
    f[n++] = &d->rotor.c;
    f[n++] = &d->rotor.s;
    f[n++] = &d->velocity.x;
    f[n++] = &d->velocity.y;
    f[n++] = &d->angular_velocity;
    f[n++] = &d->density;
    f[n++] = &d->friction;
    f[n++] = &d->restitution;
    f[n++] = &d->linear_damping;
    f[n++] = &d->angular_damping;
    f[n++] = &d->gravity_scale;
    f[n++] = &d->polygon.vertices[1].x;
    f[n++] = &d->polygon.vertices[2].y;
    return n;
}

static void bad_body_def_not_finite(void)
{
    const ga2d_body_type types[3] = {GA2D_BODY_DYNAMIC, GA2D_BODY_KINEMATIC, GA2D_BODY_STATIC};
    ga2d_real bad[3];
    fixture fx;
    int t, i, k, n;
    bad[0] = real_nan();
    bad[1] = real_inf();
    bad[2] = -real_inf();
    fixture_make(&fx);
    if (!fx.w) return;
    for (t = 0; t < 3; ++t) {
        ga2d_body_def d;
        ga2d_real *f[16];
        n = def_real_fields(&d, f);
        for (i = 0; i < n; ++i)
            for (k = 0; k < 3; ++k) {
                d = def_of(types[t], 1, 1);
                d.velocity = vec(1, 0);
                *f[i] = bad[k];
                CHECK_RESULT(ga2d_body_def_validate(&d), GA2D_ERR_NOT_FINITE);
                EXPECT_NULL_ID(&fx, &d);
            }
    }
    fixture_finish(&fx);
}

static void bad_body_def_values(void)
{
    fixture fx;
    ga2d_body_def d;
    int t;
    fixture_make(&fx);
    if (!fx.w) return;

    /* density: zero or negative refused for a dynamic body */
    d = def_of(GA2D_BODY_DYNAMIC, 0, 0);
    d.density = 0;
    CHECK_RESULT(ga2d_body_def_validate(&d), GA2D_ERR_INVALID_ARGUMENT);
    EXPECT_NULL_ID(&fx, &d);
    d.density = -1;
    CHECK_RESULT(ga2d_body_def_validate(&d), GA2D_ERR_INVALID_ARGUMENT);
    EXPECT_NULL_ID(&fx, &d);
    d.density = (ga2d_real)-0.0;
    CHECK_RESULT(ga2d_body_def_validate(&d), GA2D_ERR_INVALID_ARGUMENT);
    EXPECT_NULL_ID(&fx, &d);

    /* negative friction, restitution, damping: refused for every type */
    for (t = 0; t < GA2D_BODY_TYPE_COUNT; ++t) {
        ga2d_body_type type = (ga2d_body_type)t;
        d = def_of(type, 0, 0);
        d.friction = (ga2d_real)-0.1;
        CHECK_RESULT(ga2d_body_def_validate(&d), GA2D_ERR_INVALID_ARGUMENT);
        EXPECT_NULL_ID(&fx, &d);
        d = def_of(type, 0, 0);
        d.restitution = (ga2d_real)-0.5;
        CHECK_RESULT(ga2d_body_def_validate(&d), GA2D_ERR_INVALID_ARGUMENT);
        EXPECT_NULL_ID(&fx, &d);
        d = def_of(type, 0, 0);
        d.linear_damping = -1;
        CHECK_RESULT(ga2d_body_def_validate(&d), GA2D_ERR_INVALID_ARGUMENT);
        EXPECT_NULL_ID(&fx, &d);
        d = def_of(type, 0, 0);
        d.angular_damping = -1;
        CHECK_RESULT(ga2d_body_def_validate(&d), GA2D_ERR_INVALID_ARGUMENT);
        EXPECT_NULL_ID(&fx, &d);
        d = def_of(type, 0, 0);
        d.density = -2;
        CHECK_RESULT(ga2d_body_def_validate(&d), GA2D_ERR_INVALID_ARGUMENT);
        EXPECT_NULL_ID(&fx, &d);
    }

    /* bad type */
    d = def_of(GA2D_BODY_DYNAMIC, 0, 0);
    d.type = (ga2d_body_type)7;
    CHECK_RESULT(ga2d_body_def_validate(&d), GA2D_ERR_INVALID_ARGUMENT);
    EXPECT_NULL_ID(&fx, &d);
    d.type = (ga2d_body_type)-1;
    CHECK_RESULT(ga2d_body_def_validate(&d), GA2D_ERR_INVALID_ARGUMENT);
    EXPECT_NULL_ID(&fx, &d);
    d.type = GA2D_BODY_TYPE_COUNT;
    CHECK_RESULT(ga2d_body_def_validate(&d), GA2D_ERR_INVALID_ARGUMENT);
    EXPECT_NULL_ID(&fx, &d);

    /* bad polygons in the def, for a dynamic and a static body */
    for (t = 0; t < 2; ++t) {
        ga2d_body_type type = t ? GA2D_BODY_STATIC : GA2D_BODY_DYNAMIC;
        ga2d_vec tmp;
        d = def_of(type, 0, 0);
        /* clockwise: the box's vertices reversed */
        tmp = d.polygon.vertices[1];
        d.polygon.vertices[1] = d.polygon.vertices[3];
        d.polygon.vertices[3] = tmp;
        CHECK_RESULT(ga2d_body_def_validate(&d), GA2D_ERR_CLOCKWISE);
        EXPECT_NULL_ID(&fx, &d);
        d = def_of(type, 0, 0);
        d.polygon.count = 0; /* no polygon: a body with no shape */
        CHECK_RESULT(ga2d_body_def_validate(&d), GA2D_OK);
        d.polygon.count = 2;
        CHECK_RESULT(ga2d_body_def_validate(&d), GA2D_ERR_TOO_FEW_POINTS);
        EXPECT_NULL_ID(&fx, &d);
        d.polygon.count = MAXV + 1;
        CHECK_RESULT(ga2d_body_def_validate(&d), GA2D_ERR_TOO_MANY_POINTS);
        EXPECT_NULL_ID(&fx, &d);
        d.polygon.count = 1 << 30;
        CHECK_RESULT(ga2d_body_def_validate(&d), GA2D_ERR_TOO_MANY_POINTS);
        EXPECT_NULL_ID(&fx, &d);
        d.polygon.count = -1;
        CHECK_RESULT(ga2d_body_def_validate(&d), GA2D_ERR_INVALID_ARGUMENT);
        EXPECT_NULL_ID(&fx, &d);
        /* repeated vertex; a vertex beyond GA2D_MAX_COORDINATE */
        d = def_of(type, 0, 0);
        d.polygon.vertices[2] = d.polygon.vertices[1];
        CHECK_RESULT(ga2d_body_def_validate(&d), GA2D_ERR_REPEATED_POINTS);
        EXPECT_NULL_ID(&fx, &d);
        d = def_of(type, 0, 0);
        d.polygon.vertices[2].x = (ga2d_real)(2 * (double)GA2D_MAX_COORDINATE);
        CHECK_RESULT(ga2d_body_def_validate(&d), GA2D_ERR_TOO_LARGE);
        EXPECT_NULL_ID(&fx, &d);
#if MAXV >= 4
        /* not convex: a dart */
        {
            const ga2d_vec dart[4] = {{0, 0}, {2, 1}, {0, 2}, {1, 1}};
            d = def_of(type, 0, 0);
            d.polygon.count = 4;
            memcpy(d.polygon.vertices, dart, sizeof dart);
            CHECK_RESULT(ga2d_body_def_validate(&d), GA2D_ERR_NOT_CONVEX);
            EXPECT_NULL_ID(&fx, &d);
        }
#endif
    }

    /* a hand-filled polygon (vertices only, normals garbage) is checked
       like ga2d_polygon_make and gets its own normals */
    {
        ga2d_body_id id;
        const ga2d_polygon *p;
        int i;
        d = def_of(GA2D_BODY_DYNAMIC, 20, 20);
        for (i = 0; i < 4; ++i) d.polygon.normals[i] = vec(5, 5);
        id = ga2d_body_create(fx.w, &d);
        CHECK(!ga2d_body_id_is_null(id));
        p = ga2d_body_polygon(fx.w, id);
        CHECK(p != NULL);
        if (p) {
            ga2d_polygon box = ga2d_polygon_box((ga2d_real)0.5, (ga2d_real)0.5);
            for (i = 0; i < 4; ++i) CHECK(vec_same(p->normals[i], box.normals[i]));
        }
        CHECK_RESULT(ga2d_body_destroy(fx.w, id), GA2D_OK);
    }
    fixture_finish(&fx);
}

static void bad_world_defs(void)
{
    counting_alloc ca;
    ga2d_world_def d;
    ca_init(&ca, 0);

#define EXPECT_WORLD_REFUSED(def, expected)                      \
    do {                                                         \
        CHECK_RESULT(ga2d_world_def_validate(&(def)), expected); \
        CHECK(ga2d_world_create(&(def)) == NULL);                \
    } while (0)

    d = ca_world_def(&ca);
    d.gravity.x = real_nan();
    EXPECT_WORLD_REFUSED(d, GA2D_ERR_NOT_FINITE);
    d = ca_world_def(&ca);
    d.gravity.y = -real_inf();
    EXPECT_WORLD_REFUSED(d, GA2D_ERR_NOT_FINITE);
    d = ca_world_def(&ca);
    d.substeps = -1;
    EXPECT_WORLD_REFUSED(d, GA2D_ERR_INVALID_ARGUMENT);
    d.substeps = 5000;
    EXPECT_WORLD_REFUSED(d, GA2D_ERR_INVALID_ARGUMENT);
    d.substeps = 1025;
    EXPECT_WORLD_REFUSED(d, GA2D_ERR_INVALID_ARGUMENT);
    d = ca_world_def(&ca);
    d.integrator = (ga2d_integrator)9;
    EXPECT_WORLD_REFUSED(d, GA2D_ERR_INVALID_ARGUMENT);
    d.integrator = GA2D_INTEGRATOR_COUNT;
    EXPECT_WORLD_REFUSED(d, GA2D_ERR_INVALID_ARGUMENT);
    d = ca_world_def(&ca);
    d.rotation_update = (ga2d_rotation_update)-1;
    EXPECT_WORLD_REFUSED(d, GA2D_ERR_INVALID_ARGUMENT);
    d.rotation_update = GA2D_ROTATION_COUNT;
    EXPECT_WORLD_REFUSED(d, GA2D_ERR_INVALID_ARGUMENT);
    d = ca_world_def(&ca);
    d.length_units_per_meter = -1;
    EXPECT_WORLD_REFUSED(d, GA2D_ERR_INVALID_ARGUMENT);
    d.length_units_per_meter = real_nan();
    EXPECT_WORLD_REFUSED(d, GA2D_ERR_NOT_FINITE);
    d.length_units_per_meter = real_inf();
    EXPECT_WORLD_REFUSED(d, GA2D_ERR_NOT_FINITE);
    /* half an allocator */
    d = ca_world_def(&ca);
    d.allocator.free = NULL;
    EXPECT_WORLD_REFUSED(d, GA2D_ERR_INVALID_ARGUMENT);
    d = ca_world_def(&ca);
    d.allocator.alloc = NULL;
    EXPECT_WORLD_REFUSED(d, GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_world_def_validate(NULL), GA2D_ERR_INVALID_ARGUMENT);
#undef EXPECT_WORLD_REFUSED
    /* a refused def allocates nothing */
    CHECK(ca.attempts == 0);

    /* the edges of the substep range are accepted */
    {
        ga2d_world *w;
        d = ca_world_def(&ca);
        d.substeps = 1024;
        w = ga2d_world_create(&d);
        CHECK(w != NULL);
        ga2d_world_destroy(w);
        d.substeps = 1;
        w = ga2d_world_create(&d);
        CHECK(w != NULL);
        ga2d_world_destroy(w);
        ca_check_clean(&ca);
    }
}

/* World setters and the step refuse bad values and change nothing. */
static void bad_world_calls(void)
{
    const double bad_dt[7] = {0, -0.0, -1.0 / 60.0, -1, (double)NAN, (double)INFINITY, -(double)INFINITY};
    fixture fx;
    int i;
    fixture_make(&fx);
    if (!fx.w) return;
    for (i = 0; i < 7; ++i) EXPECT_REFUSED(&fx, ga2d_world_step(fx.w, (ga2d_real)bad_dt[i]), GA2D_ERR_INVALID_ARGUMENT);
    EXPECT_REFUSED(&fx, ga2d_world_set_gravity(fx.w, vec(0, (double)NAN)), GA2D_ERR_NOT_FINITE);
    EXPECT_REFUSED(&fx, ga2d_world_set_gravity(fx.w, vec((double)INFINITY, 0)), GA2D_ERR_NOT_FINITE);
    EXPECT_REFUSED(&fx, ga2d_world_set_substeps(fx.w, 0), GA2D_ERR_INVALID_ARGUMENT);
    EXPECT_REFUSED(&fx, ga2d_world_set_substeps(fx.w, -1), GA2D_ERR_INVALID_ARGUMENT);
    EXPECT_REFUSED(&fx, ga2d_world_set_substeps(fx.w, 1025), GA2D_ERR_INVALID_ARGUMENT);
    EXPECT_REFUSED(&fx, ga2d_world_set_integrator(fx.w, (ga2d_integrator)9), GA2D_ERR_INVALID_ARGUMENT);
    EXPECT_REFUSED(&fx, ga2d_world_set_integrator(fx.w, (ga2d_integrator)-1), GA2D_ERR_INVALID_ARGUMENT);
    EXPECT_REFUSED(&fx, ga2d_world_set_rotation_update(fx.w, (ga2d_rotation_update)-1), GA2D_ERR_INVALID_ARGUMENT);
    EXPECT_REFUSED(&fx, ga2d_world_set_rotation_update(fx.w, GA2D_ROTATION_COUNT), GA2D_ERR_INVALID_ARGUMENT);
    fixture_finish(&fx);
}

/* Body setters refuse NaN/Inf, a zero rotor, bad masses and dampings, and
   changes a body's kind does not allow; each changes nothing. */
static void bad_setters(void)
{
    fixture fx;
    ga2d_real nan_ = real_nan(), inf = real_inf();
    ga2d_mass m, good;
    int i;
    fixture_make(&fx);
    if (!fx.w) return;
    good.mass = 3;
    good.center = vec(0.1, -0.2);
    good.inertia = 2;

    for (i = 0; i < fx.n; ++i) {
        ga2d_body_id id = fx.ids[i];
        int is_dyn = ga2d_body_get_type(fx.w, id) == GA2D_BODY_DYNAMIC;
        ga2d_body_type type = ga2d_body_get_type(fx.w, id);

        EXPECT_REFUSED(&fx, ga2d_body_set_transform(fx.w, id, vec((double)NAN, 0), ga2d_rotor_identity()), GA2D_ERR_NOT_FINITE);
        EXPECT_REFUSED(&fx, ga2d_body_set_transform(fx.w, id, vec(0, (double)INFINITY), ga2d_rotor_identity()), GA2D_ERR_NOT_FINITE);
        {
            ga2d_rotor q;
            q.c = nan_;
            q.s = 0;
            EXPECT_REFUSED(&fx, ga2d_body_set_transform(fx.w, id, vec(0, 0), q), GA2D_ERR_NOT_FINITE);
            q.c = 1;
            q.s = -inf;
            EXPECT_REFUSED(&fx, ga2d_body_set_transform(fx.w, id, vec(0, 0), q), GA2D_ERR_NOT_FINITE);
            q.c = 0;
            q.s = 0;
            EXPECT_REFUSED(&fx, ga2d_body_set_transform(fx.w, id, vec(1, 1), q), GA2D_ERR_INVALID_ARGUMENT);
            q.c = (ga2d_real)-0.0;
            EXPECT_REFUSED(&fx, ga2d_body_set_transform(fx.w, id, vec(1, 1), q), GA2D_ERR_INVALID_ARGUMENT);
        }

        EXPECT_REFUSED(&fx, ga2d_body_set_velocity(fx.w, id, vec((double)NAN, 0)), GA2D_ERR_NOT_FINITE);
        EXPECT_REFUSED(&fx, ga2d_body_set_velocity(fx.w, id, vec(0, -(double)INFINITY)), GA2D_ERR_NOT_FINITE);
        EXPECT_REFUSED(&fx, ga2d_body_set_angular_velocity(fx.w, id, nan_), GA2D_ERR_NOT_FINITE);
        EXPECT_REFUSED(&fx, ga2d_body_set_angular_velocity(fx.w, id, inf), GA2D_ERR_NOT_FINITE);

        /* mass data: only dynamic bodies have one to set; for them, mass
           <= 0, negative inertia and non-finite values are refused */
        if (!is_dyn) {
            EXPECT_REFUSED(&fx, ga2d_body_set_mass_data(fx.w, id, good), GA2D_ERR_INVALID_ARGUMENT);
        } else {
            m = good;
            m.mass = 0;
            EXPECT_REFUSED(&fx, ga2d_body_set_mass_data(fx.w, id, m), GA2D_ERR_INVALID_ARGUMENT);
            m.mass = -1;
            EXPECT_REFUSED(&fx, ga2d_body_set_mass_data(fx.w, id, m), GA2D_ERR_INVALID_ARGUMENT);
            m = good;
            m.inertia = -1;
            EXPECT_REFUSED(&fx, ga2d_body_set_mass_data(fx.w, id, m), GA2D_ERR_INVALID_ARGUMENT);
        }
        m = good;
        m.mass = nan_;
        EXPECT_REFUSED(&fx, ga2d_body_set_mass_data(fx.w, id, m), GA2D_ERR_NOT_FINITE);
        m.mass = inf;
        EXPECT_REFUSED(&fx, ga2d_body_set_mass_data(fx.w, id, m), GA2D_ERR_NOT_FINITE);
        m = good;
        m.inertia = nan_;
        EXPECT_REFUSED(&fx, ga2d_body_set_mass_data(fx.w, id, m), GA2D_ERR_NOT_FINITE);
        m.inertia = inf;
        EXPECT_REFUSED(&fx, ga2d_body_set_mass_data(fx.w, id, m), GA2D_ERR_NOT_FINITE);
        m = good;
        m.center.y = nan_;
        EXPECT_REFUSED(&fx, ga2d_body_set_mass_data(fx.w, id, m), GA2D_ERR_NOT_FINITE);

        EXPECT_REFUSED(&fx, ga2d_body_set_gravity_scale(fx.w, id, nan_), GA2D_ERR_NOT_FINITE);
        EXPECT_REFUSED(&fx, ga2d_body_set_gravity_scale(fx.w, id, -inf), GA2D_ERR_NOT_FINITE);
        EXPECT_REFUSED(&fx, ga2d_body_set_damping(fx.w, id, -1, 0), GA2D_ERR_INVALID_ARGUMENT);
        EXPECT_REFUSED(&fx, ga2d_body_set_damping(fx.w, id, 0, (ga2d_real)-0.5), GA2D_ERR_INVALID_ARGUMENT);
        EXPECT_REFUSED(&fx, ga2d_body_set_damping(fx.w, id, nan_, 0), GA2D_ERR_NOT_FINITE);
        EXPECT_REFUSED(&fx, ga2d_body_set_damping(fx.w, id, 0, inf), GA2D_ERR_NOT_FINITE);

        /* a static body cannot be given a velocity */
        if (type == GA2D_BODY_STATIC) {
            EXPECT_REFUSED(&fx, ga2d_body_set_velocity(fx.w, id, vec(1, 0)), GA2D_ERR_INVALID_ARGUMENT);
            EXPECT_REFUSED(&fx, ga2d_body_set_angular_velocity(fx.w, id, 1), GA2D_ERR_INVALID_ARGUMENT);
        }
    }

    /* a fixed-rotation dynamic body cannot be spun; 0 is accepted */
    EXPECT_REFUSED(&fx, ga2d_body_set_angular_velocity(fx.w, fx.fixed, 1), GA2D_ERR_INVALID_ARGUMENT);
    EXPECT_REFUSED(&fx, ga2d_body_set_angular_velocity(fx.w, fx.fixed, (ga2d_real)-1e-30), GA2D_ERR_INVALID_ARGUMENT);
    EXPECT_REFUSED(&fx, ga2d_body_set_angular_velocity(fx.w, fx.fixed, 0), GA2D_OK);
    fixture_finish(&fx);
}

/* apply_* refuse NaN/Inf on every kind of body (the check does not depend
   on whether the force would act), and the pending force is kept. */
static void bad_forces(void)
{
    fixture fx;
    ga2d_real nan_ = real_nan(), inf = real_inf();
    int i;
    fixture_make(&fx);
    if (!fx.w) return;
    for (i = 0; i < fx.n; ++i) {
        ga2d_body_id id = fx.ids[i];
        ga2d_vec c = ga2d_body_center(fx.w, id);
        EXPECT_REFUSED(&fx, ga2d_body_apply_force(fx.w, id, vec((double)NAN, 1), c), GA2D_ERR_NOT_FINITE);
        EXPECT_REFUSED(&fx, ga2d_body_apply_force(fx.w, id, vec(1, (double)INFINITY), c), GA2D_ERR_NOT_FINITE);
        EXPECT_REFUSED(&fx, ga2d_body_apply_force(fx.w, id, vec(1, 1), vec((double)NAN, 0)), GA2D_ERR_NOT_FINITE);
        EXPECT_REFUSED(&fx, ga2d_body_apply_force(fx.w, id, vec(1, 1), vec(0, -(double)INFINITY)), GA2D_ERR_NOT_FINITE);
        EXPECT_REFUSED(&fx, ga2d_body_apply_force_to_center(fx.w, id, vec((double)NAN, 0)), GA2D_ERR_NOT_FINITE);
        EXPECT_REFUSED(&fx, ga2d_body_apply_impulse(fx.w, id, vec(0, (double)NAN), c), GA2D_ERR_NOT_FINITE);
        EXPECT_REFUSED(&fx, ga2d_body_apply_impulse(fx.w, id, vec(-(double)INFINITY, 0), c), GA2D_ERR_NOT_FINITE);
        EXPECT_REFUSED(&fx, ga2d_body_apply_impulse(fx.w, id, vec(1, 0), vec((double)INFINITY, 0)), GA2D_ERR_NOT_FINITE);
        EXPECT_REFUSED(&fx, ga2d_body_apply_torque(fx.w, id, nan_), GA2D_ERR_NOT_FINITE);
        EXPECT_REFUSED(&fx, ga2d_body_apply_torque(fx.w, id, -inf), GA2D_ERR_NOT_FINITE);
        EXPECT_REFUSED(&fx, ga2d_body_apply_angular_impulse(fx.w, id, nan_), GA2D_ERR_NOT_FINITE);
        EXPECT_REFUSED(&fx, ga2d_body_apply_angular_impulse(fx.w, id, inf), GA2D_ERR_NOT_FINITE);
    }
    fixture_finish(&fx);
}

/* Every function that takes a world answers NULL with an error or zero. */
static void null_world(void)
{
    ga2d_body_def d = def_of(GA2D_BODY_DYNAMIC, 0, 0);
    ga2d_world_counters c = ga2d_world_get_counters(NULL);
    ga2d_body_id id;
    ga2d_mass m;
    m.mass = 1;
    m.center = vec(0, 0);
    m.inertia = 1;
    id.index1 = 1;
    id.generation = 1;

    ga2d_world_destroy(NULL);
    CHECK_RESULT(ga2d_world_step(NULL, (ga2d_real)DT), GA2D_ERR_INVALID_ARGUMENT);
    CHECK(ga2d_world_time(NULL) == 0);
    CHECK(c.body_count == 0 && c.moving_body_count == 0 && c.integrated_bodies == 0 && c.force_evaluations == 0 &&
          c.rotation_updates == 0 && c.step_count == 0);
    CHECK(vec_same(ga2d_world_gravity(NULL), vec(0, 0)));
    CHECK_RESULT(ga2d_world_set_gravity(NULL, vec(0, 1)), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_world_set_substeps(NULL, 4), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_world_set_integrator(NULL, GA2D_INTEGRATOR_RK4), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_world_set_rotation_update(NULL, GA2D_ROTATION_LINEAR), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_world_set_force_callback(NULL, NULL, NULL), GA2D_ERR_INVALID_ARGUMENT);

    CHECK(ga2d_body_id_is_null(ga2d_body_create(NULL, &d)));
    CHECK(ga2d_body_id_is_null(ga2d_body_create(NULL, NULL)));
    CHECK_RESULT(ga2d_body_def_validate(NULL), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_body_destroy(NULL, id), GA2D_ERR_INVALID_ARGUMENT);
    check_getters_refuse(NULL, id);
    CHECK_RESULT(ga2d_body_set_transform(NULL, id, vec(1, 1), ga2d_rotor_identity()), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_body_set_velocity(NULL, id, vec(1, 1)), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_body_set_angular_velocity(NULL, id, 1), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_body_set_mass_data(NULL, id, m), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_body_set_gravity_scale(NULL, id, 1), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_body_set_damping(NULL, id, 0, 0), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_body_set_user_data(NULL, id, NULL), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_body_apply_force(NULL, id, vec(1, 0), vec(0, 0)), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_body_apply_force_to_center(NULL, id, vec(1, 0)), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_body_apply_torque(NULL, id, 1), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_body_apply_impulse(NULL, id, vec(1, 0), vec(0, 0)), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_body_apply_angular_impulse(NULL, id, 1), GA2D_ERR_INVALID_ARGUMENT);

    /* a NULL def to a real world: the null id, nothing created */
    {
        ga2d_world *w = ga2d_world_create(NULL);
        CHECK(w != NULL);
        CHECK(ga2d_body_id_is_null(ga2d_body_create(w, NULL)));
        CHECK(ga2d_world_get_counters(w).body_count == 0);
        ga2d_world_destroy(w);
    }
}

/* A finite mass or inertia so small that 1/m or 1/I overflows must be
   refused (or, if accepted, must not turn the body into NaN/Inf: with no
   gravity and no force a step must leave it at rest).  Same for a density
   that gives such a mass. */
static void tiny_mass_refused_or_finite(void)
{
    const double tiny[2] = {REAL_MIN, REAL_MIN / 4}; /* the smallest normal, a subnormal */
    int k, which;
    for (k = 0; k < 2; ++k) {
        ga2d_real t = (ga2d_real)tiny[k];
        for (which = 0; which < 3; ++which) {
            ga2d_world *w = world_with_gravity(0, 0);
            ga2d_body_def d = def_of(GA2D_BODY_DYNAMIC, 1, 1);
            ga2d_body_id id;
            ga2d_result r = GA2D_OK;
            if (!w) {
                CHECK(w != NULL);
                return;
            }
            if (which == 0) d.density = t;
            id = ga2d_body_create(w, &d);
            if (which > 0) {
                ga2d_mass m;
                CHECK(!ga2d_body_id_is_null(id));
                m.mass = which == 1 ? t : 1;
                m.center = vec(0, 0);
                m.inertia = which == 2 ? t : 1;
                r = ga2d_body_set_mass_data(w, id, m);
            }
            if (!ga2d_body_id_is_null(id) && r == GA2D_OK) {
                CHECK_RESULT(ga2d_world_step(w, (ga2d_real)DT), GA2D_OK);
                if (!vec_finite(ga2d_body_velocity(w, id)) || !real_finite(ga2d_body_angular_velocity(w, id)) ||
                    !vec_finite(ga2d_body_center(w, id)) || !real_finite(ga2d_body_rotor(w, id).c))
                    test_fail(__FILE__, __LINE__,
                              "%s %g accepted, and one step at rest made the body non-finite: v = (%g, %g), w = %g",
                              which == 0 ? "density" : which == 1 ? "mass" : "inertia", tiny[k],
                              (double)ga2d_body_velocity(w, id).x, (double)ga2d_body_velocity(w, id).y,
                              (double)ga2d_body_angular_velocity(w, id));
            }
            ga2d_world_destroy(w);
        }
    }
}

/* set_transform refuses the zero rotor; a rotor too small to normalize
   (subnormal) is the same thing and must not silently become the identity:
   it is either refused, or normalized to the direction it has. */
static void tiny_rotor_refused_or_kept(void)
{
    ga2d_world *w = ga2d_world_create(NULL);
    ga2d_body_def d = def_of(GA2D_BODY_DYNAMIC, 0, 0);
    ga2d_body_id id;
    ga2d_rotor q;
    ga2d_result r;
    if (!w) {
        CHECK(w != NULL);
        return;
    }
    id = ga2d_body_create(w, &d);
    q.c = 0;
    q.s = (ga2d_real)(REAL_MIN / 4); /* a quarter turn, subnormal length */
    r = ga2d_body_set_transform(w, id, vec(0, 0), q);
    if (r == GA2D_OK) {
        /* accepted: then it must be the quarter turn it names */
        ga2d_rotor got = ga2d_body_rotor(w, id);
        if (!(got.c == 0 && got.s == 1))
            test_fail(__FILE__, __LINE__, "set_transform(rotor (0, %g)) returned OK and set the rotor (%g, %g), not (0, 1)",
                      REAL_MIN / 4, (double)got.c, (double)got.s);
    } else {
        CHECK_RESULT(r, GA2D_ERR_INVALID_ARGUMENT);
    }
    ga2d_world_destroy(w);
}

/* Finite inputs that overflow the state: a force far from the centre whose
   torque r ^ F overflows, and impulses that add up past the largest real.
   Either the call refuses (state unchanged), or the step reports the
   non-finite body (DESIGN 7) instead of returning OK with it. */
static void overflow_refused_or_reported(void)
{
    double big = sqrt(REAL_MAX) * 4; /* big * big overflows */
    int k;
    for (k = 0; k < 2; ++k) {
        ga2d_world *w = world_with_gravity(0, 0);
        ga2d_body_def d = def_of(GA2D_BODY_DYNAMIC, 0, 0);
        ga2d_body_id id;
        ga2d_result r1, r2, rs;
        if (!w) {
            CHECK(w != NULL);
            return;
        }
        id = ga2d_body_create(w, &d);
        if (k == 0) {
            r1 = ga2d_body_apply_force(w, id, vec(0, big), vec(big, 0));
            r2 = GA2D_OK;
        } else {
            r1 = ga2d_body_apply_impulse(w, id, vec(REAL_MAX, 0), ga2d_body_center(w, id));
            r2 = ga2d_body_apply_impulse(w, id, vec(REAL_MAX, 0), ga2d_body_center(w, id));
        }
        rs = ga2d_world_step(w, (ga2d_real)DT);
        if (r1 == GA2D_OK && r2 == GA2D_OK && rs == GA2D_OK &&
            (!vec_finite(ga2d_body_velocity(w, id)) || !real_finite(ga2d_body_angular_velocity(w, id)) ||
             !real_finite(ga2d_body_rotor(w, id).c) || !vec_finite(ga2d_body_center(w, id))))
            test_fail(__FILE__, __LINE__,
                      "%s: every call and the step returned OK, and the body is non-finite: v = (%g, %g), w = %g",
                      k == 0 ? "apply_force(F = (0, big), at (big, 0))" : "apply_impulse(REAL_MAX) twice",
                      (double)ga2d_body_velocity(w, id).x, (double)ga2d_body_velocity(w, id).y,
                      (double)ga2d_body_angular_velocity(w, id));
        ga2d_world_destroy(w);
    }
}

/* ============================================================= allocator */
/* All memory comes from the world def's allocator, with its ctx, and goes
   back with the size it was allocated with. */
static void counting_allocator(void)
{
    counting_alloc ca;
    ga2d_world_def wd;
    ga2d_world *w;
    ga2d_body_id ids[300];
    int i;
    g_bad_ctx = 0;
    ca_init(&ca, 0);
    wd = ca_world_def(&ca);
    w = ga2d_world_create(&wd);
    CHECK(w != NULL);
    if (!w) return;
    CHECK(ca.allocs >= 1 && ca.live_bytes > 0);
    for (i = 0; i < 300; ++i) {
        ga2d_body_def d = def_of((ga2d_body_type)(i % 3), i, 0);
        d.velocity = vec(0, 1);
        ids[i] = ga2d_body_create(w, &d);
        CHECK(!ga2d_body_id_is_null(ids[i]));
    }
    CHECK_RESULT(ga2d_world_set_integrator(w, GA2D_INTEGRATOR_RK4), GA2D_OK);
    CHECK_RESULT(ga2d_world_step(w, (ga2d_real)DT), GA2D_OK);
    for (i = 0; i < 300; i += 3) CHECK_RESULT(ga2d_body_destroy(w, ids[i]), GA2D_OK);
    CHECK_RESULT(ga2d_world_set_integrator(w, GA2D_INTEGRATOR_VERLET), GA2D_OK);
    CHECK_RESULT(ga2d_world_step(w, (ga2d_real)DT), GA2D_OK);
    CHECK(ca.allocs > 3); /* the world, its bodies, the moving list, RK4 scratch */
    CHECK(ca.failures == 0);
    ga2d_world_destroy(w);
    ca_check_clean(&ca);
}

/* The failing-allocator scenario: create a world, 100 bodies of mixed
   types, switch to RK4, step, 100 more bodies, destroy a few, recreate.
   At each call that meets the failing allocation: the failure is reported
   (NULL / null id / OUT_OF_MEMORY), the world is bit-identical, it still
   steps, and the same call succeeds once allocation works again. */
typedef struct oom_run {
    counting_alloc *ca;
    ga2d_world *w;
    ga2d_body_id ids[256];
    int n;
    int failed_calls;
    snapshot before, after;
} oom_run;

static void oom_after_failure(oom_run *o, const char *what)
{
    long attempts = o->ca->attempts;
    snap_take(&o->after, o->w, o->ids, o->n, 1);
    if (!snap_same(&o->before, &o->after))
        test_fail(__FILE__, __LINE__, "%s failed for lack of memory and changed the world (fail_at %ld)", what,
                  o->ca->fail_at);
    CHECK_RESULT(ga2d_world_step(o->w, (ga2d_real)DT), GA2D_OK);
    CHECK(o->ca->attempts == attempts); /* a step allocates nothing */
    ++o->failed_calls;
}

static void oom_create(oom_run *o, int i)
{
    ga2d_body_def d = def_of((ga2d_body_type)(i % 3), (i % 16) * 2, (i / 16) * 2);
    int tries;
    d.velocity = vec(0.5, i % 4);
    d.angular_velocity = (ga2d_real)(0.1 * (i % 5));
    d.user_data = &g_tags[i % 16];
    for (tries = 0; tries < 2; ++tries) {
        long failures = o->ca->failures;
        ga2d_body_id id;
        snap_take(&o->before, o->w, o->ids, o->n, 1);
        id = ga2d_body_create(o->w, &d);
        if (o->ca->failures == failures) {
            CHECK(!ga2d_body_id_is_null(id));
            if (o->n < 256) o->ids[o->n++] = id;
            return;
        }
        CHECK(ga2d_body_id_is_null(id));
        oom_after_failure(o, "ga2d_body_create");
    }
    CHECK(0); /* failed twice: the allocator fails only once */
}

static void oom_set_integrator(oom_run *o, ga2d_integrator integ)
{
    int tries;
    for (tries = 0; tries < 2; ++tries) {
        long failures = o->ca->failures;
        ga2d_result r;
        snap_take(&o->before, o->w, o->ids, o->n, 1);
        r = ga2d_world_set_integrator(o->w, integ);
        if (o->ca->failures == failures) {
            CHECK_RESULT(r, GA2D_OK);
            return;
        }
        CHECK_RESULT(r, GA2D_ERR_OUT_OF_MEMORY);
        oom_after_failure(o, "ga2d_world_set_integrator");
    }
    CHECK(0);
}

static void oom_scenario(counting_alloc *ca, int *failed_calls)
{
    oom_run o;
    ga2d_world_def wd = ca_world_def(ca);
    int i, tries;
    memset(&o, 0, sizeof o);
    o.ca = ca;
    for (tries = 0; tries < 2 && !o.w; ++tries) {
        long failures = ca->failures;
        o.w = ga2d_world_create(&wd);
        if (ca->failures != failures) {
            CHECK(o.w == NULL);
            CHECK(ca->live_bytes == 0);
            ++o.failed_calls;
        }
    }
    CHECK(o.w != NULL);
    if (!o.w) return;
    for (i = 0; i < 100; ++i) oom_create(&o, i);
    CHECK_RESULT(ga2d_world_step(o.w, (ga2d_real)DT), GA2D_OK);
    oom_set_integrator(&o, GA2D_INTEGRATOR_RK4);
    CHECK_RESULT(ga2d_world_step(o.w, (ga2d_real)DT), GA2D_OK);
    for (i = 100; i < 200; ++i) oom_create(&o, i);
    CHECK_RESULT(ga2d_world_step(o.w, (ga2d_real)DT), GA2D_OK);
    for (i = 0; i < 30; ++i) CHECK_RESULT(ga2d_body_destroy(o.w, o.ids[i * 5]), GA2D_OK);
    for (i = 200; i < 230; ++i) oom_create(&o, i);
    CHECK_RESULT(ga2d_world_step(o.w, (ga2d_real)DT), GA2D_OK);
    CHECK(ga2d_world_get_counters(o.w).body_count == 200);
    ga2d_world_destroy(o.w);
    snap_free(&o.before);
    snap_free(&o.after);
    *failed_calls = o.failed_calls;
}

static void failing_allocator(void)
{
    counting_alloc ca;
    long total, k;
    int failed_calls = 0;
    g_bad_ctx = 0;
    ca_init(&ca, 0);
    oom_scenario(&ca, &failed_calls);
    total = ca.attempts;
    CHECK(failed_calls == 0);
    CHECK(total >= 10); /* world, bodies and moving lists growing, RK4 scratch */
    ca_check_clean(&ca);
    for (k = 1; k <= total; ++k) {
        ca_init(&ca, k);
        oom_scenario(&ca, &failed_calls);
        if (ca.failures != 1 || failed_calls != 1)
            test_fail(__FILE__, __LINE__, "fail_at %ld: %ld allocation failures, %d calls reported one", k, ca.failures,
                      failed_calls);
        ca_check_clean(&ca);
    }
}

/* ===================================================== static, kinematic */
/* Static bodies never move, whatever is applied to them, and cost nothing:
   with 10000 of them and one dynamic body, a step updates one body per
   substep. */
#define STATICS 10000
static void static_bodies(void)
{
    static ga2d_body_id ids[STATICS];
    snapshot before, after;
    ga2d_world *w = ga2d_world_create(NULL);
    ga2d_body_def d;
    ga2d_body_id dyn;
    ga2d_world_counters c;
    int i, s;
    memset(&before, 0, sizeof before);
    memset(&after, 0, sizeof after);
    CHECK(w != NULL);
    if (!w) return;
    for (i = 0; i < STATICS; ++i) {
        d = def_of(GA2D_BODY_STATIC, i % 100 * 2, i / 100 * 2);
        d.rotor = ga2d_rotor_from_angle((ga2d_real)(0.01 * (i % 17)));
        d.velocity = vec(1, 1); /* ignored: static */
        d.angular_velocity = 3;
        ids[i] = ga2d_body_create(w, &d);
        CHECK(!ga2d_body_id_is_null(ids[i]));
    }
    d = def_of(GA2D_BODY_DYNAMIC, -10, 10);
    dyn = ga2d_body_create(w, &d);
    CHECK(vec_same(ga2d_body_velocity(w, ids[5]), vec(0, 0)) && ga2d_body_angular_velocity(w, ids[5]) == 0);
    snap_take(&before, w, ids, STATICS, 0);
    for (s = 0; s < 3; ++s) {
        for (i = 0; i < STATICS; i += 7) {
            ga2d_vec c0 = ga2d_body_center(w, ids[i]);
            CHECK_RESULT(ga2d_body_apply_force(w, ids[i], vec(100, 50), vec(0, 0)), GA2D_OK);
            CHECK_RESULT(ga2d_body_apply_force_to_center(w, ids[i], vec(100, 50)), GA2D_OK);
            CHECK_RESULT(ga2d_body_apply_torque(w, ids[i], 30), GA2D_OK);
            CHECK_RESULT(ga2d_body_apply_impulse(w, ids[i], vec(-5, 5), ga2d_vec_add(c0, vec(1, 1))), GA2D_OK);
            CHECK_RESULT(ga2d_body_apply_angular_impulse(w, ids[i], 2), GA2D_OK);
        }
        CHECK_RESULT(ga2d_world_step(w, (ga2d_real)DT), GA2D_OK);
        c = ga2d_world_get_counters(w);
        CHECK(c.body_count == STATICS + 1);
        CHECK(c.moving_body_count == 1);
        CHECK(c.integrated_bodies == 4); /* 1 body x 4 substeps */
        CHECK(c.rotation_updates == 0);  /* the dynamic body does not turn */
        CHECK(c.step_count == s + 1);
    }
    snap_take(&after, w, ids, STATICS, 0);
    CHECK(snap_same(&before, &after));
    CHECK(ga2d_body_kinetic_energy(w, ids[3]) == 0);
    CHECK(ga2d_body_velocity(w, dyn).y < 0); /* gravity acts on the dynamic one */
    snap_free(&before);
    snap_free(&after);
    ga2d_world_destroy(w);
}

/* A kinematic body moves exactly with its velocity, under gravity and with
   forces, torques and impulses applied every step (which do nothing).
   Over N = 480 substeps of h (2 s at 60 Hz, 4 substeps):
   centre: each substep rounds v h and the sum, <= eps (|x| + |v h|), so
   |dx| <= N eps Xmax with Xmax = |x0| + |v| T (plus the double sum of the
   time, 120 additions of dt: 120 eps_double T |v|, negligible but counted);
   angle: each exact rotor update rounds the exp series (<= 1 eps), the
   product q exp (<= 2 eps in angle) and the renormalisation (<= 1 eps):
   <= 4 eps per substep, so the rotor is within (4 N + 2) eps of
   (cos wt, sin wt).  wt = 4 rad, past pi: the rotor wraps. */
static void kinematic_body(void)
{
    ga2d_world *w = ga2d_world_create(NULL);
    ga2d_body_def d = def_of(GA2D_BODY_KINEMATIC, 1, 2);
    ga2d_body_id id;
    ga2d_vec c0, v;
    ga2d_real om;
    const int steps = 120, n_sub = 4 * 120;
    double T, xmax, tol_x, tol_q;
    int k;
    CHECK(w != NULL);
    if (!w) return;
    d.velocity = vec(3, -1.5);
    d.angular_velocity = 2;
    d.gravity_scale = 3;
    id = ga2d_body_create(w, &d);
    CHECK(!ga2d_body_id_is_null(id));
    c0 = ga2d_body_center(w, id);
    v = ga2d_body_velocity(w, id);
    om = ga2d_body_angular_velocity(w, id);
    CHECK(vec_same(v, d.velocity) && om == 2);
    CHECK(ga2d_body_kinetic_energy(w, id) >= 0);
    for (k = 0; k < steps; ++k) {
        ga2d_vec c = ga2d_body_center(w, id);
        CHECK_RESULT(ga2d_body_apply_force(w, id, vec(1000, 1000), ga2d_vec_add(c, vec(1, 0))), GA2D_OK);
        CHECK_RESULT(ga2d_body_apply_force_to_center(w, id, vec(-50, 20)), GA2D_OK);
        CHECK_RESULT(ga2d_body_apply_torque(w, id, 100), GA2D_OK);
        CHECK_RESULT(ga2d_body_apply_impulse(w, id, vec(5, 5), ga2d_vec_add(c, vec(0, 1))), GA2D_OK);
        CHECK_RESULT(ga2d_body_apply_angular_impulse(w, id, 7), GA2D_OK);
        CHECK_RESULT(ga2d_world_step(w, (ga2d_real)DT), GA2D_OK);
    }
    /* velocity and angular velocity: not one bit changed */
    CHECK(vec_same(ga2d_body_velocity(w, id), v));
    CHECK(ga2d_body_angular_velocity(w, id) == om);
    T = ga2d_world_time(w);
    CHECK_NEAR(T, steps * (double)(ga2d_real)DT, steps * 1e-16 * T);
    xmax = len2((double)c0.x, (double)c0.y) + len2((double)v.x, (double)v.y) * T;
    tol_x = n_sub * REAL_EPS * xmax + 120 * DBL_EPSILON * T * 4;
    tol_q = (4 * n_sub + 2) * REAL_EPS;
    CHECK_NEAR(ga2d_body_center(w, id).x, (double)c0.x + (double)v.x * T, tol_x);
    CHECK_NEAR(ga2d_body_center(w, id).y, (double)c0.y + (double)v.y * T, tol_x);
    CHECK_NEAR(ga2d_body_rotor(w, id).c, cos((double)om * T), tol_q);
    CHECK_NEAR(ga2d_body_rotor(w, id).s, sin((double)om * T), tol_q);
    /* the origin follows: position = centre - (local centre) q, two
       roundings of values <= Xmax + |local centre| */
    {
        ga2d_mass m = ga2d_body_mass_data(w, id);
        ga2d_vec lc = ga2d_rotate(ga2d_body_rotor(w, id), m.center);
        ga2d_vec p = ga2d_body_position(w, id), c = ga2d_body_center(w, id);
        CHECK_NEAR(p.x, (double)c.x - (double)lc.x, 4 * REAL_EPS * (xmax + 1));
        CHECK_NEAR(p.y, (double)c.y - (double)lc.y, 4 * REAL_EPS * (xmax + 1));
    }
    ga2d_world_destroy(w);
}

/* ================================================================ locking */
typedef struct lock_probe {
    ga2d_body_id dyn, stat;
    ga2d_vec force;
    ga2d_real torque;
    int calls;
    double times[32];
    ga2d_vec vel[32];
    ga2d_real omega[32];
} lock_probe;

/* Inside the force callback: every change but forces and torques is
   refused with LOCKED; the getters and the forces work. */
static void lock_callback(ga2d_world *w, void *ctx)
{
    lock_probe *p = (lock_probe *)ctx;
    ga2d_body_def d = def_of(GA2D_BODY_DYNAMIC, 5, 5);
    ga2d_mass m;
    ga2d_vec c = ga2d_body_center(w, p->dyn);
    if (p->calls < 32) {
        p->times[p->calls] = ga2d_world_time(w);
        p->vel[p->calls] = ga2d_body_velocity(w, p->dyn);
        p->omega[p->calls] = ga2d_body_angular_velocity(w, p->dyn);
    }
    ++p->calls;
    m.mass = 5;
    m.center = vec(0, 0);
    m.inertia = 1;

    CHECK(ga2d_body_id_is_null(ga2d_body_create(w, &d)));
    CHECK_RESULT(ga2d_body_destroy(w, p->dyn), GA2D_ERR_LOCKED);
    CHECK_RESULT(ga2d_body_destroy(w, p->stat), GA2D_ERR_LOCKED);
    CHECK_RESULT(ga2d_body_set_transform(w, p->dyn, vec(9, 9), ga2d_rotor_identity()), GA2D_ERR_LOCKED);
    CHECK_RESULT(ga2d_body_set_velocity(w, p->dyn, vec(9, 9)), GA2D_ERR_LOCKED);
    CHECK_RESULT(ga2d_body_set_angular_velocity(w, p->dyn, 9), GA2D_ERR_LOCKED);
    CHECK_RESULT(ga2d_body_set_mass_data(w, p->dyn, m), GA2D_ERR_LOCKED);
    CHECK_RESULT(ga2d_body_set_gravity_scale(w, p->dyn, 9), GA2D_ERR_LOCKED);
    CHECK_RESULT(ga2d_body_set_damping(w, p->dyn, 9, 9), GA2D_ERR_LOCKED);
    CHECK_RESULT(ga2d_body_set_user_data(w, p->dyn, NULL), GA2D_ERR_LOCKED);
    CHECK_RESULT(ga2d_body_apply_impulse(w, p->dyn, vec(9, 9), c), GA2D_ERR_LOCKED);
    CHECK_RESULT(ga2d_body_apply_angular_impulse(w, p->dyn, 9), GA2D_ERR_LOCKED);
    CHECK_RESULT(ga2d_world_step(w, (ga2d_real)DT), GA2D_ERR_LOCKED);
    CHECK_RESULT(ga2d_world_set_gravity(w, vec(0, -99)), GA2D_ERR_LOCKED);
    CHECK_RESULT(ga2d_world_set_substeps(w, 8), GA2D_ERR_LOCKED);
    CHECK_RESULT(ga2d_world_set_integrator(w, GA2D_INTEGRATOR_VERLET), GA2D_ERR_LOCKED);
    CHECK_RESULT(ga2d_world_set_rotation_update(w, GA2D_ROTATION_LINEAR), GA2D_ERR_LOCKED);
    CHECK_RESULT(ga2d_world_set_force_callback(w, NULL, NULL), GA2D_ERR_LOCKED);

    /* getters */
    CHECK(ga2d_body_is_valid(w, p->dyn) && ga2d_body_is_valid(w, p->stat));
    CHECK(ga2d_body_user_data(w, p->dyn) == &g_tags[10]);
    CHECK(ga2d_body_get_type(w, p->dyn) == GA2D_BODY_DYNAMIC);
    CHECK(ga2d_body_mass_data(w, p->dyn).mass > 0);
    CHECK(ga2d_body_polygon(w, p->dyn) != NULL);
    CHECK(ga2d_world_get_counters(w).body_count == 2);
    CHECK(vec_same(ga2d_world_gravity(w), vec(0, 0)));

    /* forces: accepted (on the static body: accepted, no effect) */
    CHECK_RESULT(ga2d_body_apply_force(w, p->dyn, p->force, c), GA2D_OK);
    CHECK_RESULT(ga2d_body_apply_torque(w, p->dyn, p->torque), GA2D_OK);
    CHECK_RESULT(ga2d_body_apply_force_to_center(w, p->stat, vec(1, 1)), GA2D_OK);
    CHECK_RESULT(ga2d_body_apply_torque(w, p->stat, 1), GA2D_OK);
}

/* Symplectic Euler, 4 substeps of h = dt/4: evaluation k of a step sees
   time t0 + k h (one double rounding: 2 ulp of t) and the velocity after k
   kicks, v = k (F/m) h; after the step v = (F/m) dt and w = (tau/I) dt, four
   additions each: 4 eps.  RK4: 16 evaluations at t0 + s h + {0, h/2, h/2, h}. */
static void locked_inside_callback(void)
{
    static const double rk4_at[4] = {0, 0.5, 0.5, 1};
    ga2d_world *w = world_with_gravity(0, 0);
    lock_probe p;
    ga2d_body_def d;
    ga2d_real dt = (ga2d_real)DT, h = dt / 4;
    ga2d_mass m;
    double a, alpha, t0;
    int step, k;
    CHECK(w != NULL);
    if (!w) return;
    memset(&p, 0, sizeof p);
    d = def_of(GA2D_BODY_DYNAMIC, 0, 0);
    d.polygon = ga2d_polygon_box(1, (ga2d_real)0.5);
    d.user_data = &g_tags[10];
    p.dyn = ga2d_body_create(w, &d);
    d = def_of(GA2D_BODY_STATIC, 0, -3);
    p.stat = ga2d_body_create(w, &d);
    p.force = vec(6, -3);
    p.torque = (ga2d_real)1.5;
    m = ga2d_body_mass_data(w, p.dyn);
    a = (double)p.force.x / (double)m.mass;
    alpha = (double)p.torque / (double)m.inertia;
    CHECK_RESULT(ga2d_world_set_force_callback(w, lock_callback, &p), GA2D_OK);

    for (step = 0; step < 2; ++step) {
        ga2d_vec v0 = ga2d_body_velocity(w, p.dyn);
        ga2d_real w0 = ga2d_body_angular_velocity(w, p.dyn);
        t0 = ga2d_world_time(w);
        p.calls = 0;
        CHECK_RESULT(ga2d_world_step(w, dt), GA2D_OK);
        CHECK(p.calls == 4);
        CHECK(ga2d_world_get_counters(w).force_evaluations == 4);
        for (k = 0; k < 4 && k < p.calls; ++k) {
            double t = t0 + (double)h * k;
            CHECK_NEAR(p.times[k], t, 2 * DBL_EPSILON * t);
            CHECK_NEAR(p.vel[k].x, (double)v0.x + a * k * (double)h, 4 * REAL_EPS * ((double)v0.x + a * (double)dt));
            CHECK_NEAR(p.omega[k], (double)w0 + alpha * k * (double)h, 4 * REAL_EPS * ((double)w0 + alpha * (double)dt));
        }
        /* back outside: the world's own time, and the callback's forces
           acted while its refused calls did nothing */
        CHECK(ga2d_world_time(w) == t0 + (double)dt);
        CHECK_NEAR(ga2d_body_velocity(w, p.dyn).x, (double)v0.x + a * (double)dt, 4 * REAL_EPS * ((double)v0.x + a * (double)dt));
        CHECK_NEAR(ga2d_body_velocity(w, p.dyn).y, (double)v0.y - a / 2 * (double)dt,
                   4 * REAL_EPS * (-(double)v0.y + a / 2 * (double)dt));
        CHECK_NEAR(ga2d_body_angular_velocity(w, p.dyn), (double)w0 + alpha * (double)dt,
                   4 * REAL_EPS * ((double)w0 + alpha * (double)dt));
        CHECK(ga2d_world_get_counters(w).body_count == 2);
        CHECK(ga2d_body_user_data(w, p.dyn) == &g_tags[10]);
        CHECK(vec_same(ga2d_body_velocity(w, p.stat), vec(0, 0)));
        CHECK(vec_same(ga2d_body_position(w, p.stat), vec(0, -3)));
    }

    /* RK4: the stage times */
    CHECK_RESULT(ga2d_world_set_integrator(w, GA2D_INTEGRATOR_RK4), GA2D_OK);
    t0 = ga2d_world_time(w);
    p.calls = 0;
    CHECK_RESULT(ga2d_world_step(w, dt), GA2D_OK);
    CHECK(p.calls == 16);
    for (k = 0; k < 16 && k < p.calls; ++k) {
        double t = t0 + (double)h * (k / 4) + rk4_at[k % 4] * (double)h;
        CHECK_NEAR(p.times[k], t, 4 * DBL_EPSILON * t);
    }
    CHECK(ga2d_world_time(w) == t0 + (double)dt);
    ga2d_world_destroy(w);
}

/* ============================================================= mass data */
/* set_mass_data keeps the origin, moves the centre to p + c' q, and gives
   the new centre the velocity of that body point, v + (c' - c) Omega.
   Roundings: the centre is a sum of the origin and a rotated offset, each
   step <= 2 eps of values <= |p| + |c'|: 8 eps (|p| + |c'| + |c|); the
   velocity adds one product and one sum to it: 4 eps (|v| + |w| |c' - c|). */
static void mass_data(void)
{
    ga2d_world *w = world_with_gravity(0, 0);
    ga2d_body_def d = def_of(GA2D_BODY_DYNAMIC, 3, 4);
    ga2d_body_id id;
    ga2d_mass m, got;
    ga2d_vec p0, c0, v0, c1, v1, lc, p;
    ga2d_rotor q;
    ga2d_real om;
    double tolp, tolv, ex, ey, ke;
    CHECK(w != NULL);
    if (!w) return;
    d.polygon = ga2d_polygon_box(1, (ga2d_real)0.5);
    d.rotor = ga2d_rotor_from_angle((ga2d_real)0.3);
    d.velocity = vec(1, 2);
    d.angular_velocity = (ga2d_real)1.5;
    id = ga2d_body_create(w, &d);
    CHECK(!ga2d_body_id_is_null(id));
    p0 = ga2d_body_position(w, id);
    c0 = ga2d_body_center(w, id);
    v0 = ga2d_body_velocity(w, id);
    q = ga2d_body_rotor(w, id);
    om = ga2d_body_angular_velocity(w, id);

    m.mass = 5;
    m.center = vec(0.2, -0.1);
    m.inertia = 2;
    CHECK_RESULT(ga2d_body_set_mass_data(w, id, m), GA2D_OK);
    got = ga2d_body_mass_data(w, id);
    CHECK(got.mass == m.mass && got.inertia == m.inertia && vec_same(got.center, m.center));
    CHECK(ga2d_body_rotor(w, id).c == q.c && ga2d_body_rotor(w, id).s == q.s);
    CHECK(ga2d_body_angular_velocity(w, id) == om);

    tolp = 8 * REAL_EPS * (len2((double)p0.x, (double)p0.y) + 1);
    CHECK_NEAR(ga2d_body_position(w, id).x, p0.x, tolp);
    CHECK_NEAR(ga2d_body_position(w, id).y, p0.y, tolp);
    lc = ga2d_rotate(q, m.center);
    c1 = ga2d_body_center(w, id);
    CHECK_NEAR(c1.x, (double)p0.x + (double)lc.x, tolp);
    CHECK_NEAR(c1.y, (double)p0.y + (double)lc.y, tolp);
    /* v1 = v0 + w perp(c1 - c0), perp(r) = (-r.y, r.x) */
    ex = (double)v0.x - (double)om * ((double)c1.y - (double)c0.y);
    ey = (double)v0.y + (double)om * ((double)c1.x - (double)c0.x);
    v1 = ga2d_body_velocity(w, id);
    tolv = 4 * REAL_EPS * (len2((double)v0.x, (double)v0.y) + (double)om * 1) + (double)om * 2 * tolp;
    CHECK_NEAR(v1.x, ex, tolv);
    CHECK_NEAR(v1.y, ey, tolv);
    /* the body's old origin point still moves with the same rigid motion:
       velocity_at(origin) = v0 + w perp(p0 - c0) before and after */
    {
        ga2d_vec vo = ga2d_body_velocity_at(w, id, p0);
        double ox = (double)v0.x - (double)om * ((double)p0.y - (double)c0.y);
        double oy = (double)v0.y + (double)om * ((double)p0.x - (double)c0.x);
        CHECK_NEAR(vo.x, ox, 2 * tolv);
        CHECK_NEAR(vo.y, oy, 2 * tolv);
    }

    /* velocity_at(p) = v + w perp(p - c): one product and sums of values
       <= |v| + |w| |p - c|: 4 eps of that */
    p = vec(-2.5, 7.25);
    {
        ga2d_vec va = ga2d_body_velocity_at(w, id, p);
        double rx = (double)p.x - (double)c1.x, ry = (double)p.y - (double)c1.y;
        double tol = 4 * REAL_EPS * (len2((double)v1.x, (double)v1.y) + (double)om * len2(rx, ry));
        CHECK_NEAR(va.x, (double)v1.x - (double)om * ry, tol);
        CHECK_NEAR(va.y, (double)v1.y + (double)om * rx, tol);
    }
    /* kinetic energy = (m v.v + I w^2)/2: a few products and sums, 4 eps */
    ke = 0.5 * 5 * ((double)v1.x * (double)v1.x + (double)v1.y * (double)v1.y) + 0.5 * 2 * (double)om * (double)om;
    CHECK_NEAR(ga2d_body_kinetic_energy(w, id), ke, 4 * REAL_EPS * ke);

    /* the new mass acts: a force F at the centre for one step gives
       dv = F/m' dt (4 additions: 4 eps), a torque dw = tau/I' dt */
    {
        ga2d_real dt = (ga2d_real)DT;
        CHECK_RESULT(ga2d_body_apply_force_to_center(w, id, vec(10, 0)), GA2D_OK);
        CHECK_RESULT(ga2d_body_apply_torque(w, id, 4), GA2D_OK);
        CHECK_RESULT(ga2d_world_step(w, dt), GA2D_OK);
        CHECK_NEAR(ga2d_body_velocity(w, id).x, (double)v1.x + 10.0 / 5.0 * (double)dt,
                   4 * REAL_EPS * ((double)v1.x + 2 * (double)dt));
        CHECK_NEAR(ga2d_body_angular_velocity(w, id), (double)om + 4.0 / 2.0 * (double)dt,
                   4 * REAL_EPS * ((double)om + 2 * (double)dt));
    }

    /* inertia 0: the body stops turning and no torque or off-centre
       impulse turns it again; linear impulses still act, dv = P/m */
    {
        ga2d_rotor q1;
        ga2d_vec va, c = ga2d_body_center(w, id);
        int k;
        m.inertia = 0;
        CHECK_RESULT(ga2d_body_set_mass_data(w, id, m), GA2D_OK);
        CHECK(ga2d_body_angular_velocity(w, id) == 0);
        CHECK(ga2d_body_mass_data(w, id).inertia == 0);
        va = ga2d_body_velocity(w, id);
        q1 = ga2d_body_rotor(w, id);
        CHECK_RESULT(ga2d_body_apply_impulse(w, id, vec(0, 5), ga2d_vec_add(c, vec(2, 0))), GA2D_OK);
        CHECK_RESULT(ga2d_body_apply_angular_impulse(w, id, 3), GA2D_OK);
        CHECK(ga2d_body_angular_velocity(w, id) == 0);
        CHECK(ga2d_body_velocity(w, id).x == va.x);
        CHECK_NEAR(ga2d_body_velocity(w, id).y, (double)va.y + 1, 2 * REAL_EPS * ((double)va.y + 1));
        for (k = 0; k < 10; ++k) {
            CHECK_RESULT(ga2d_body_apply_torque(w, id, 50), GA2D_OK);
            CHECK_RESULT(ga2d_body_apply_force(w, id, vec(0, 10), ga2d_vec_add(ga2d_body_center(w, id), vec(-1, 0))), GA2D_OK);
            CHECK_RESULT(ga2d_world_step(w, (ga2d_real)DT), GA2D_OK);
        }
        CHECK(ga2d_body_angular_velocity(w, id) == 0);
        CHECK(ga2d_body_rotor(w, id).c == q1.c && ga2d_body_rotor(w, id).s == q1.s);
        /* kinetic energy without the rotation */
        va = ga2d_body_velocity(w, id);
        ke = 0.5 * 5 * ((double)va.x * (double)va.x + (double)va.y * (double)va.y);
        CHECK_NEAR(ga2d_body_kinetic_energy(w, id), ke, 4 * REAL_EPS * ke);
    }
    ga2d_world_destroy(w);
}

/* The def's fixed_rotation: the given angular velocity is dropped and no
   torque, off-centre impulse, angular impulse or off-centre force turns
   the body: its rotor keeps every bit.  A linear impulse gives P/m (one
   division and one addition: 2 eps). */
static void fixed_rotation(void)
{
    ga2d_world *w = ga2d_world_create(NULL);
    ga2d_body_def d = def_of(GA2D_BODY_DYNAMIC, 0, 0);
    ga2d_body_id id;
    ga2d_rotor q0;
    ga2d_real mass;
    ga2d_vec v0, c;
    int k;
    CHECK(w != NULL);
    if (!w) return;
    d.fixed_rotation = 1;
    d.rotor = ga2d_rotor_from_angle((ga2d_real)0.4);
    d.angular_velocity = 3;
    d.polygon = ga2d_polygon_box(2, (ga2d_real)0.5);
    id = ga2d_body_create(w, &d);
    CHECK(!ga2d_body_id_is_null(id));
    CHECK(ga2d_body_angular_velocity(w, id) == 0);
    q0 = ga2d_body_rotor(w, id);
    mass = ga2d_body_mass_data(w, id).mass;
    v0 = ga2d_body_velocity(w, id);
    c = ga2d_body_center(w, id);
    CHECK_RESULT(ga2d_body_apply_impulse(w, id, vec(4, 0), ga2d_vec_add(c, vec(0, 1.5))), GA2D_OK);
    CHECK_NEAR(ga2d_body_velocity(w, id).x, (double)v0.x + 4 / (double)mass, 2 * REAL_EPS * (4 / (double)mass));
    CHECK(ga2d_body_angular_velocity(w, id) == 0);
    for (k = 0; k < 30; ++k) {
        c = ga2d_body_center(w, id);
        CHECK_RESULT(ga2d_body_apply_torque(w, id, 100), GA2D_OK);
        CHECK_RESULT(ga2d_body_apply_force(w, id, vec(0, 40), ga2d_vec_add(c, vec(2, 0))), GA2D_OK);
        CHECK_RESULT(ga2d_body_apply_impulse(w, id, vec(0, 1), ga2d_vec_add(c, vec(-2, 0))), GA2D_OK);
        CHECK_RESULT(ga2d_body_apply_angular_impulse(w, id, 5), GA2D_OK);
        CHECK_RESULT(ga2d_world_step(w, (ga2d_real)DT), GA2D_OK);
    }
    CHECK(ga2d_body_angular_velocity(w, id) == 0);
    CHECK(ga2d_body_rotor(w, id).c == q0.c && ga2d_body_rotor(w, id).s == q0.s);
    CHECK(ga2d_world_get_counters(w).rotation_updates == 0);
    /* a new mass data keeps it fixed */
    {
        ga2d_mass m;
        m.mass = 2;
        m.center = vec(0.5, 0);
        m.inertia = 1;
        CHECK_RESULT(ga2d_body_set_mass_data(w, id, m), GA2D_OK);
        CHECK_RESULT(ga2d_body_apply_torque(w, id, 100), GA2D_OK);
        CHECK_RESULT(ga2d_world_step(w, (ga2d_real)DT), GA2D_OK);
        CHECK(ga2d_body_angular_velocity(w, id) == 0);
        CHECK(ga2d_body_rotor(w, id).c == q0.c && ga2d_body_rotor(w, id).s == q0.s);
    }
    ga2d_world_destroy(w);
}

/* ================================================ forces cleared per step */
/* A force applied once acts in exactly one step: symplectic Euler with no
   gravity gives dv = F/m dt (4 kicks of F/m h: 4 roundings of values <=
   |dv|, plus the division: 5 eps), then the next step changes v by
   nothing at all.  The same for a torque (dw = tau/I dt), for an
   off-centre force (both), and two forces applied before one step add. */
static void forces_cleared_after_step(void)
{
    ga2d_world *w = world_with_gravity(0, 0);
    ga2d_body_def d = def_of(GA2D_BODY_DYNAMIC, 0, 0);
    ga2d_real dt = (ga2d_real)DT;
    ga2d_body_id id;
    ga2d_mass m;
    ga2d_vec v, c, v1;
    ga2d_real om, om1;
    double dvx, dvy, dw, r;
    CHECK(w != NULL);
    if (!w) return;
    d.polygon = ga2d_polygon_box((ga2d_real)1.5, (ga2d_real)0.5);
    id = ga2d_body_create(w, &d);
    m = ga2d_body_mass_data(w, id);

    /* a force at the centre */
    CHECK_RESULT(ga2d_body_apply_force_to_center(w, id, vec(3, -2)), GA2D_OK);
    CHECK_RESULT(ga2d_world_step(w, dt), GA2D_OK);
    v = ga2d_body_velocity(w, id);
    dvx = 3 / (double)m.mass * (double)dt;
    dvy = -2 / (double)m.mass * (double)dt;
    CHECK_NEAR(v.x, dvx, 5 * REAL_EPS * fabs(dvx));
    CHECK_NEAR(v.y, dvy, 5 * REAL_EPS * fabs(dvy));
    CHECK(ga2d_body_angular_velocity(w, id) == 0);
    CHECK_RESULT(ga2d_world_step(w, dt), GA2D_OK);
    CHECK(vec_same(ga2d_body_velocity(w, id), v));

    /* a torque */
    CHECK_RESULT(ga2d_body_apply_torque(w, id, 2), GA2D_OK);
    CHECK_RESULT(ga2d_world_step(w, dt), GA2D_OK);
    om = ga2d_body_angular_velocity(w, id);
    dw = 2 / (double)m.inertia * (double)dt;
    CHECK_NEAR(om, dw, 5 * REAL_EPS * dw);
    CHECK(vec_same(ga2d_body_velocity(w, id), v));
    CHECK_RESULT(ga2d_world_step(w, dt), GA2D_OK);
    CHECK(ga2d_body_angular_velocity(w, id) == om);

    /* two forces before one step add; one is off-centre: F = (0, 4) at
       r = (1, 0) from the centre adds tau = r ^ F = 4 */
    c = ga2d_body_center(w, id);
    r = 1;
    CHECK_RESULT(ga2d_body_apply_force(w, id, vec(0, 4), ga2d_vec_add(c, vec(r, 0))), GA2D_OK);
    CHECK_RESULT(ga2d_body_apply_force_to_center(w, id, vec(-1, 0)), GA2D_OK);
    CHECK_RESULT(ga2d_world_step(w, dt), GA2D_OK);
    v1 = ga2d_body_velocity(w, id);
    om1 = ga2d_body_angular_velocity(w, id);
    CHECK_NEAR(v1.x, (double)v.x - 1 / (double)m.mass * (double)dt, 5 * REAL_EPS * (fabs((double)v.x) + (double)dt / (double)m.mass));
    CHECK_NEAR(v1.y, (double)v.y + 4 / (double)m.mass * (double)dt, 5 * REAL_EPS * (fabs((double)v.y) + 4 * (double)dt / (double)m.mass));
    CHECK_NEAR(om1, (double)om + 4 * r / (double)m.inertia * (double)dt, 5 * REAL_EPS * ((double)om + 4 * (double)dt / (double)m.inertia));
    CHECK_RESULT(ga2d_world_step(w, dt), GA2D_OK);
    CHECK(vec_same(ga2d_body_velocity(w, id), v1));
    CHECK(ga2d_body_angular_velocity(w, id) == om1);

    /* a refused step (dt = 0) does not use up the pending force: it acts
       in the next real step */
    CHECK_RESULT(ga2d_body_apply_force_to_center(w, id, vec(5, 0)), GA2D_OK);
    CHECK_RESULT(ga2d_world_step(w, 0), GA2D_ERR_INVALID_ARGUMENT);
    CHECK_RESULT(ga2d_world_step(w, dt), GA2D_OK);
    CHECK_NEAR(ga2d_body_velocity(w, id).x, (double)v1.x + 5 / (double)m.mass * (double)dt,
               5 * REAL_EPS * (fabs((double)v1.x) + 5 * (double)dt / (double)m.mass));
    ga2d_world_destroy(w);
}

void suite_world(void)
{
    test_run("world: default world and body defs", defaults);
    test_run("world: zero-initialised world def means the defaults", zero_world_def);
    test_run("world: zero-initialised body def means the defaults", zero_body_def);
    test_run("world: ga2d_world_create(NULL) is the default world", create_null_def);
    test_run("world: ids: null, destroy, reuse, forged, generations", ids_and_generations);
    test_run("world: 5000 bodies, half destroyed and recreated, keep their state", many_bodies);
    test_run("world: NaN/Inf in every body def field refused, world unchanged", bad_body_def_not_finite);
    test_run("world: bad density, friction, damping, type, polygon refused", bad_body_def_values);
    test_run("world: bad world defs refused, nothing allocated", bad_world_defs);
    test_run("world: step and world setters refuse bad values, world unchanged", bad_world_calls);
    test_run("world: body setters refuse bad values, world unchanged", bad_setters);
    test_run("world: apply_* refuse NaN/Inf, pending forces kept", bad_forces);
    test_run("world: NULL world to every function: an error or zero", null_world);
    test_run("world: a mass or density whose inverse overflows is refused or harmless", tiny_mass_refused_or_finite);
    test_run("world: a subnormal rotor is refused, not turned into the identity", tiny_rotor_refused_or_kept);
    test_run("world: finite forces/impulses that overflow are refused or reported", overflow_refused_or_reported);
    test_run("world: counting allocator gets every byte back, with its sizes", counting_allocator);
    test_run("world: failing allocator at every allocation: reported, unchanged, recoverable", failing_allocator);
    test_run("world: 10000 static bodies never move and cost nothing", static_bodies);
    test_run("world: a kinematic body moves exactly with its velocity", kinematic_body);
    test_run("world: locked inside the force callback; stage times", locked_inside_callback);
    test_run("world: set_mass_data keeps the origin, moves the centre with the motion", mass_data);
    test_run("world: fixed rotation never turns", fixed_rotation);
    test_run("world: forces act for exactly one step", forces_cleared_after_step);
}
