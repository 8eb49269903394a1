/* World fuzzing: raw bytes -> a world (its def's knobs: substeps, solver,
   integrator, rotor update, switches, tolerances, length unit, an
   allocator that can fail), bodies of every type (boxes, regular polygons,
   hulls of decoded points, hand-filled polygon structs), then a sequence
   of operations: steps with all kinds of dt, destroy, create, every
   setter, forces, torques, impulses, sleep and wake, teleports, filters,
   a force field that also tries what a locked world must refuse, and the
   queries.  Values are ordinary most of the time (so that bodies touch
   and the solver works) and extreme on a per-body / per-call switch.

   What is checked (the header's promises):
     - every call answers with a ga2d_result (no crash, no sanitizer
       report, no leak: the allocator counts every byte back by the end);
     - a refused call changes nothing it was asked to change (the body's
       state as every getter reports it, bit for bit; the body count);
     - a valid body def makes a body unless an allocation failed, and an
       allocation that fails in a call is reported by it
       (OUT_OF_MEMORY, or the null id);
     - a step with dt not finite and > 0 is refused and nothing changes;
     - a step reports OK, OUT_OF_MEMORY (exactly when an allocation failed
       in it) or NOT_FINITE (a body it contained, named by
       ga2d_world_error_body); after OK and NOT_FINITE every awake moving
       body has a finite state and a unit rotor;
     - inside the force callback, everything but forces, torques and
       getters is refused with LOCKED. */
#ifndef GA2D_FUZZ_WORLD_H
#define GA2D_FUZZ_WORLD_H

#include "fuzz_common.h"

#define FW_MAX_IDS 48
#define FW_MAX_OPS 200
/* step work budget: substeps x solver passes x (bodies + 1), summed over
   the steps of one input, so that no input takes more than ~0.1 s */
#define FW_WORK_BUDGET 400000L

#ifdef FUZZ_VERBOSE
#define FW_TRACE(args) (fprintf args)
#else
#define FW_TRACE(args) ((void)0)
#endif

typedef struct fw_state {
    fz_reader rd;
    ga2d_world *w;
    fz_alloc alloc;
    ga2d_body_id ids[FW_MAX_IDS];
    int nids;
    /* what the world was told, for the work budget */
    int substeps, passes, rk4;
    double units; /* length units per metre: the step's and gravity's bounds scale with it */
    long work;
    /* the force field */
    int field_kind, field_forbidden, field_calls;
    ga2d_real field_k;
    int tag;
    /* called before a body is destroyed (NULL: nothing), for harnesses
       built on this one that keep things of their own on bodies */
    void (*before_destroy)(struct fw_state *s, ga2d_body_id id);
} fw_state;

/* An ordinary value (k/16 scale) unless `wild`: then anything. */
static ga2d_real fw_val(fw_state *s, double scale, int wild)
{
    return wild ? fz_real(&s->rd, scale) : fz_narrow((double)(int8_t)fz_u8(&s->rd) * scale / 16);
}
static ga2d_real fw_pos(fw_state *s, double scale, int wild)
{
    return wild ? fz_real_pos(&s->rd, scale) : fz_narrow((double)fz_u8(&s->rd) * scale / 256);
}
static ga2d_vec fw_vec(fw_state *s, double scale, int wild)
{
    ga2d_vec v;
    v.x = fw_val(s, scale, wild);
    v.y = fw_val(s, scale, wild);
    return v;
}

static int fw_rotor_ok(ga2d_rotor q) { return fz_finite((double)q.c) && fz_finite((double)q.s); }

/* ------------------------------------------------------ body snapshot */
/* Everything the getters say about one body, for "refused: unchanged". */
typedef struct fw_snap {
    int valid, type, awake;
    ga2d_vec position, center, velocity;
    ga2d_rotor q;
    ga2d_real w;
    ga2d_mass mass;
    ga2d_filter filter;
    void *user;
    ga2d_aabb fat;
} fw_snap;

static void fw_take(const ga2d_world *w, ga2d_body_id id, fw_snap *o)
{
    memset(o, 0, sizeof *o);
    o->valid = ga2d_body_is_valid(w, id);
    o->type = (int)ga2d_body_get_type(w, id);
    o->awake = ga2d_body_is_awake(w, id);
    o->position = ga2d_body_position(w, id);
    o->center = ga2d_body_center(w, id);
    o->velocity = ga2d_body_velocity(w, id);
    o->q = ga2d_body_rotor(w, id);
    o->w = ga2d_body_angular_velocity(w, id);
    o->mass = ga2d_body_mass_data(w, id);
    o->filter = ga2d_body_filter(w, id);
    o->user = ga2d_body_user_data(w, id);
    o->fat = ga2d_body_fat_aabb(w, id);
}

/* The id an operation acts on: a tracked one (live or destroyed), the
   null id, or a forged one. */
static ga2d_body_id fw_id(fw_state *s)
{
    unsigned k = fz_u8(&s->rd);
    ga2d_body_id id = ga2d_body_id_null();
    if (s->nids > 0 && k < 240) return s->ids[k % (unsigned)s->nids];
    if (k >= 248) {
        id.index1 = (uint32_t)(k - 247);
        id.generation = (uint32_t)fz_u8(&s->rd);
    }
    return id;
}

/* ------------------------------------------------------------ polygons */
static ga2d_polygon fw_polygon(fw_state *s, int wild)
{
    ga2d_polygon p;
    int kind = fz_pick(&s->rd, 8), i, n;
    memset(&p, 0, sizeof p);
    switch (kind) {
    /* (each read its own statement: a function's arguments are evaluated
       in no set order, and gcc and clang differ, so an input would make
       another scene in each) */
    case 0: case 1: case 2: {
        ga2d_real hw = fw_pos(s, 2, wild) + (wild ? 0 : (ga2d_real)0.05);
        ga2d_real hh = fw_pos(s, 2, wild) + (wild ? 0 : (ga2d_real)0.05);
        return ga2d_polygon_box(hw, hh);
    }
    case 3: case 4: {
        int count = 3 + fz_pick(&s->rd, GA2D_MAX_POLYGON_VERTICES - 2);
        return ga2d_polygon_regular(count, fw_pos(s, 2, wild) + (wild ? 0 : (ga2d_real)0.05));
    }
    case 5: case 6: {
        ga2d_vec pts[16];
        n = 3 + fz_pick(&s->rd, 14);
        for (i = 0; i < n; ++i) pts[i] = fw_vec(s, 2, wild);
        if (ga2d_polygon_hull(pts, n, &p) != GA2D_OK) p = ga2d_polygon_box(1, (ga2d_real)0.5);
        return p;
    }
    default:
        /* a hand-filled struct: validation must catch whatever it holds */
        p.count = (int)(int8_t)fz_u8(&s->rd) % (GA2D_MAX_POLYGON_VERTICES + 3);
        for (i = 0; i < GA2D_MAX_POLYGON_VERTICES; ++i) {
            p.vertices[i] = fw_vec(s, 2, 1);
            p.normals[i] = fw_vec(s, 1, 1);
        }
        return p;
    }
}

/* --------------------------------------------------------------- bodies */
static ga2d_body_def fw_body_def(fw_state *s)
{
    ga2d_body_def d = ga2d_default_body_def();
    unsigned flags = fz_u8(&s->rd), raw = fz_u8(&s->rd), t = raw % 20;
    int wild = (flags & 7) == 0;
    /* a hand-made def: its zero fields are the defaults */
    if (raw >= 200) d.internal_cookie = 0;
    d.type = t < 5 ? GA2D_BODY_STATIC : t < 8 ? GA2D_BODY_KINEMATIC : t < 19 ? GA2D_BODY_DYNAMIC : GA2D_BODY_TYPE_COUNT;
    d.polygon = fw_polygon(s, wild && (flags & 8));
    d.position = fw_vec(s, 4, wild);
    if (flags & 16) {
        d.rotor = wild ? ga2d_rotor_identity() : ga2d_rotor_from_angle(fw_val(s, 4, 0));
        if (wild) {
            d.rotor.c = fz_real(&s->rd, 1);
            d.rotor.s = fz_real(&s->rd, 1);
        }
    }
    if (flags & 32) {
        d.velocity = fw_vec(s, 8, wild);
        d.angular_velocity = fw_val(s, 8, wild);
    }
    if (flags & 64) {
        d.density = fw_pos(s, 4, wild);
        d.friction = fw_pos(s, 1, wild);
        d.restitution = fw_pos(s, 1, wild);
        d.linear_damping = fw_pos(s, 1, wild);
        d.angular_damping = fw_pos(s, 1, wild);
        d.gravity_scale = fw_val(s, 2, wild);
    }
    if (flags & 128) {
        unsigned f = fz_u8(&s->rd);
        d.fixed_rotation = (int)(f & 1);
        d.is_awake = (f & 2) ? 0 : 1;
        d.filter.category_bits = (f & 4) ? (uint32_t)1 << (fz_u8(&s->rd) & 31) : 1;
        d.filter.mask_bits = (f & 8) ? fz_u32(&s->rd) : 0xFFFFFFFFu;
        d.filter.group_index = (f & 16) ? (int32_t)(int8_t)fz_u8(&s->rd) : 0;
    }
    d.user_data = &s->tag;
    return d;
}

static void fw_create(fw_state *s)
{
    ga2d_body_def d = fw_body_def(s);
    ga2d_result valid = ga2d_body_def_validate(&d);
    int before = ga2d_world_get_counters(s->w).body_count;
    long failures = s->alloc.failures;
    ga2d_body_id id;
    if (s->nids == FW_MAX_IDS) return;
    id = ga2d_body_create(s->w, &d);
#ifdef FUZZ_VERBOSE
    {
        int j_;
        for (j_ = 0; j_ < d.polygon.count && j_ < GA2D_MAX_POLYGON_VERTICES; ++j_)
            fprintf(stderr, "   v%d (%.9g, %.9g)\n", j_, (double)d.polygon.vertices[j_].x, (double)d.polygon.vertices[j_].y);
    }
#endif
    FW_TRACE((stderr, "create type %d pos (%g %g) v (%g %g) w %g rotor (%g %g) density %g count %d: %s -> %u\n", (int)d.type,
              (double)d.position.x, (double)d.position.y, (double)d.velocity.x, (double)d.velocity.y,
              (double)d.angular_velocity, (double)d.rotor.c, (double)d.rotor.s, (double)d.density, d.polygon.count,
              ga2d_result_string(valid), id.index1));
    if (valid != GA2D_OK || s->alloc.failures != failures) {
        /* refused, or out of memory: nothing made */
        FUZZ_CHECK(ga2d_body_id_is_null(id));
        FUZZ_CHECK(ga2d_world_get_counters(s->w).body_count == before);
        return;
    }
    FUZZ_CHECK(!ga2d_body_id_is_null(id) && ga2d_body_is_valid(s->w, id));
    FUZZ_CHECK(ga2d_world_get_counters(s->w).body_count == before + 1);
    FUZZ_CHECK(ga2d_body_get_type(s->w, id) == d.type);
    FUZZ_CHECK(ga2d_body_user_data(s->w, id) == &s->tag);
    {
        /* the origin comes back as given: position = (p + c q) - c q with
           c the centroid (|c| <= the polygon's reach R): three roundings of
           values <= |p| + R, each eps/2 of them, plus the rotation's */
        ga2d_vec p = ga2d_body_position(s->w, id);
        const ga2d_polygon *poly = ga2d_body_polygon(s->w, id);
        double reach = 0, size;
        int i;
        /* a def without a polygon makes a body without a shape */
        int count = d.polygon.count;
        FUZZ_CHECK(count == 0 ? poly == NULL : (poly != NULL && poly->count == count));
        for (i = 0; poly && i < poly->count; ++i)
            reach = fmax(reach, fabs((double)poly->vertices[i].x) + fabs((double)poly->vertices[i].y));
        size = fabs((double)d.position.x) + fabs((double)d.position.y) + reach;
        if (size < 1e-3 * FZ_REAL_MAX)
            FUZZ_CHECK(fabs((double)p.x - (double)d.position.x) + fabs((double)p.y - (double)d.position.y) <=
                       16 * FZ_EPS * size + 8 * FZ_TINY);
    }
    s->ids[s->nids++] = id;
}

/* ----------------------------------------------------------- the field */
static void fw_field(ga2d_world *w, void *ctx)
{
    fw_state *s = (fw_state *)ctx;
    int i;
    ++s->field_calls;
    for (i = 0; i < s->nids; ++i) {
        ga2d_body_id id = s->ids[i];
        ga2d_vec c, v, f;
        ga2d_result r;
        if (!ga2d_body_is_valid(w, id)) continue;
        c = ga2d_body_center(w, id);
        v = ga2d_body_velocity(w, id);
        switch (s->field_kind) {
        case 0: f = ga2d_vec_scale(c, -s->field_k); break;          /* spring to the origin */
        case 1: f = ga2d_vec_scale(v, -s->field_k); break;          /* drag */
        default: f = ga2d_vec_make(s->field_k, -s->field_k); break; /* wind */
        }
        r = ga2d_body_apply_force_to_center(w, id, f);
        FUZZ_CHECK(r == GA2D_OK || r == GA2D_ERR_NOT_FINITE);
        r = ga2d_body_apply_torque(w, id, s->field_k);
        FUZZ_CHECK(r == GA2D_OK || r == GA2D_ERR_NOT_FINITE);
        r = ga2d_body_apply_force(w, id, f, ga2d_vec_add(c, ga2d_vec_make(1, 0)));
        FUZZ_CHECK(r == GA2D_OK || r == GA2D_ERR_NOT_FINITE);
    }
    if (s->field_forbidden && s->field_calls % 5 == 1) {
        /* the world is locked: everything else is refused */
        ga2d_body_def d = ga2d_default_body_def();
        d.polygon = ga2d_polygon_box((ga2d_real)0.5, (ga2d_real)0.5);
        ga2d_body_id any = s->nids ? s->ids[0] : ga2d_body_id_null();
        int count = ga2d_world_get_counters(w).body_count;
        ga2d_debug_draw dd = ga2d_default_debug_draw();
        FUZZ_CHECK(ga2d_world_step(w, (ga2d_real)(1.0 / 60)) == GA2D_ERR_LOCKED);
        FUZZ_CHECK(ga2d_body_id_is_null(ga2d_body_create(w, &d)));
        FUZZ_CHECK(ga2d_world_get_counters(w).body_count == count);
        FUZZ_CHECK(ga2d_world_set_gravity(w, ga2d_vec_make(0, 0)) == GA2D_ERR_LOCKED);
        FUZZ_CHECK(ga2d_world_set_substeps(w, 2) == GA2D_ERR_LOCKED);
        FUZZ_CHECK(ga2d_world_set_integrator(w, GA2D_INTEGRATOR_RK4) == GA2D_ERR_LOCKED);
        FUZZ_CHECK(ga2d_world_set_solver(w, GA2D_SOLVER_PGS_NGS) == GA2D_ERR_LOCKED);
        FUZZ_CHECK(ga2d_world_set_rotation_update(w, GA2D_ROTATION_LINEAR) == GA2D_ERR_LOCKED);
        FUZZ_CHECK(ga2d_world_set_force_callback(w, NULL, NULL) == GA2D_ERR_LOCKED);
        FUZZ_CHECK(ga2d_world_enable_sleep(w, 0) == GA2D_ERR_LOCKED);
        FUZZ_CHECK(ga2d_world_enable_friction(w, 0) == GA2D_ERR_LOCKED);
        FUZZ_CHECK(ga2d_world_draw(w, &dd) == GA2D_ERR_LOCKED);
        {
            /* joints: made, destroyed, set: refused first of all */
            ga2d_revolute_joint_def rj = ga2d_default_revolute_joint_def();
            ga2d_distance_joint_def dj = ga2d_default_distance_joint_def();
            ga2d_weld_joint_def wj = ga2d_default_weld_joint_def();
            ga2d_motor_joint_def mj = ga2d_default_motor_joint_def();
            ga2d_joint_id jid, made;
            int joints = ga2d_world_get_counters(w).joint_count;
            jid.index1 = 1;
            jid.generation = 1;
            rj.body_a = dj.body_a = wj.body_a = mj.body_a = any;
            rj.body_b = dj.body_b = wj.body_b = mj.body_b = s->nids > 1 ? s->ids[1] : any;
            FUZZ_CHECK(ga2d_revolute_joint_create_checked(w, &rj, &made) == GA2D_ERR_LOCKED && ga2d_joint_id_is_null(made));
            FUZZ_CHECK(ga2d_distance_joint_create_checked(w, &dj, &made) == GA2D_ERR_LOCKED && ga2d_joint_id_is_null(made));
            FUZZ_CHECK(ga2d_joint_id_is_null(ga2d_weld_joint_create(w, &wj)));
            FUZZ_CHECK(ga2d_joint_id_is_null(ga2d_motor_joint_create(w, &mj)));
            FUZZ_CHECK(ga2d_joint_destroy(w, jid) == GA2D_ERR_LOCKED);
            FUZZ_CHECK(ga2d_revolute_joint_set_motor_speed(w, jid, 1) == GA2D_ERR_LOCKED);
            FUZZ_CHECK(ga2d_distance_joint_enable_limit(w, jid, 1) == GA2D_ERR_LOCKED);
            FUZZ_CHECK(ga2d_weld_joint_set_linear_spring(w, jid, 1, 1) == GA2D_ERR_LOCKED);
            FUZZ_CHECK(ga2d_motor_joint_set_angular_offset(w, jid, 1) == GA2D_ERR_LOCKED);
            FUZZ_CHECK(ga2d_world_get_counters(w).joint_count == joints);
        }
        if (ga2d_body_is_valid(w, any)) {
            fw_snap before, after;
            fw_take(w, any, &before);
            FUZZ_CHECK(ga2d_body_destroy(w, any) == GA2D_ERR_LOCKED);
            FUZZ_CHECK(ga2d_body_set_velocity(w, any, ga2d_vec_make(1, 1)) == GA2D_ERR_LOCKED);
            FUZZ_CHECK(ga2d_body_set_transform(w, any, ga2d_vec_make(1, 1), ga2d_rotor_identity()) == GA2D_ERR_LOCKED);
            FUZZ_CHECK(ga2d_body_set_awake(w, any, 0) == GA2D_ERR_LOCKED);
            FUZZ_CHECK(ga2d_body_apply_impulse(w, any, ga2d_vec_make(1, 1), ga2d_vec_make(0, 0)) == GA2D_ERR_LOCKED);
            FUZZ_CHECK(ga2d_body_set_filter(w, any, ga2d_default_filter()) == GA2D_ERR_LOCKED);
            FUZZ_CHECK(ga2d_body_set_angular_velocity(w, any, 1) == GA2D_ERR_LOCKED);
            FUZZ_CHECK(ga2d_body_set_gravity_scale(w, any, 2) == GA2D_ERR_LOCKED);
            fw_take(w, any, &after);
            FUZZ_CHECK(memcmp(&before, &after, sizeof before) == 0);
        }
    }
}

/* -------------------------------------------------------------- checks */
/* After a step that reported GA2D_OK: every awake moving body is finite,
   with a unit rotor.  Each rotor update renormalizes (a Newton step that
   leaves |q| = 1 within about 3 eps, or a division by the norm), so 64 eps
   is a wide margin. */
static void fw_check_finite(fw_state *s)
{
    int i;
    for (i = 0; i < s->nids; ++i) {
        ga2d_body_id id = s->ids[i];
        ga2d_vec c, v;
        ga2d_rotor q;
        double nq;
        if (!ga2d_body_is_valid(s->w, id) || !ga2d_body_is_awake(s->w, id) ||
            ga2d_body_get_type(s->w, id) == GA2D_BODY_STATIC)
            continue;
        c = ga2d_body_center(s->w, id);
        v = ga2d_body_velocity(s->w, id);
        q = ga2d_body_rotor(s->w, id);
        FW_TRACE((stderr, "  body %u: c (%g %g) v (%g %g) q (%g %g) w %g\n", id.index1, (double)c.x, (double)c.y, (double)v.x,
                  (double)v.y, (double)q.c, (double)q.s, (double)ga2d_body_angular_velocity(s->w, id)));
        FUZZ_CHECK(fz_finite_vec(c) && fz_finite_vec(v) && fw_rotor_ok(q));
        FUZZ_CHECK(fz_finite((double)ga2d_body_angular_velocity(s->w, id)));
        nq = hypot((double)q.c, (double)q.s);
        FUZZ_CHECK(fabs(nq - 1) <= 64 * FZ_EPS);
    }
}

static void fw_check_counts(fw_state *s)
{
    int i, live = 0;
    ga2d_world_counters c = ga2d_world_get_counters(s->w);
    for (i = 0; i < s->nids; ++i) live += ga2d_body_is_valid(s->w, s->ids[i]);
    FUZZ_CHECK(c.body_count == live);
    FUZZ_CHECK(c.moving_body_count >= 0 && c.moving_body_count <= live);
    FUZZ_CHECK(c.awake_body_count >= 0 && c.awake_body_count <= c.moving_body_count);
    FUZZ_CHECK(c.touching_count >= 0 && c.touching_count <= c.pair_count);
}

/* What any step that was not refused promises: an allocation that failed
   in it is reported (OUT_OF_MEMORY), and only then; a body driven to a
   state that is not finite is contained (NOT_FINITE, named by
   ga2d_world_error_body, put back where the step began) so that after OK
   and after NOT_FINITE every awake body is finite. */
static void fw_check_step(fw_state *s, ga2d_result r, long failures_before)
{
    ga2d_body_id bad = ga2d_world_error_body(s->w);
    FUZZ_CHECK(r == GA2D_OK || r == GA2D_ERR_OUT_OF_MEMORY || r == GA2D_ERR_NOT_FINITE);
    if (s->alloc.failures != failures_before) FUZZ_CHECK(r == GA2D_ERR_OUT_OF_MEMORY);
    if (r == GA2D_ERR_OUT_OF_MEMORY) FUZZ_CHECK(s->alloc.failures != failures_before);
    if (r == GA2D_OK) FUZZ_CHECK(ga2d_body_id_is_null(bad));
    if (r == GA2D_ERR_NOT_FINITE) FUZZ_CHECK(ga2d_body_is_valid(s->w, bad));
    if (r == GA2D_OK || r == GA2D_ERR_NOT_FINITE) fw_check_finite(s);
}

/* The bounds of GA2D_MAX_TIME_STEP and GA2D_MAX_GRAVITY, with a margin of
   a part in 1e3 either side for the library's own rounding. */
static double fw_max_gravity(const fw_state *s) { return GA2D_MAX_GRAVITY * s->units; }
static int fw_step_too_large(const fw_state *s, double dt, double tol)
{
    ga2d_vec g = ga2d_world_gravity(s->w);
    double h = dt / s->substeps, gx = (double)g.x, gy = (double)g.y, m = fmax(fabs(gx), fabs(gy));
    /* |g| h^2, scaled first: |g| alone overflows at g near the largest real */
    double gh2 = m == 0 ? 0 : (m * h * h) * hypot(gx / m, gy / m);
    return dt > GA2D_MAX_TIME_STEP * tol || gh2 > GA2D_LINEAR_SLOP * s->units * tol;
}

/* ---------------------------------------------------------------- step */
static void fw_step(fw_state *s)
{
    static const double dts[12] = {1.0 / 60, 1.0 / 30, 1.0 / 120, 1.0 / 240, 0.5, 0, -1.0 / 60, 1e-30, 1e-45, 10, 1e6, 1e38};
    unsigned k = fz_u8(&s->rd);
    ga2d_real dt;
    long long steps_before;
    long failures;
    ga2d_result r;
    long cost;
    if (k < 200) dt = fz_narrow(dts[k % 5]);
    else if (k < 240) dt = fz_narrow(dts[k % 12]);
    else dt = fz_real(&s->rd, 1);
    cost = (long)s->substeps * s->passes * (s->rk4 ? 4 : 1) * (ga2d_world_get_counters(s->w).body_count + 1);
    if (s->work + cost > FW_WORK_BUDGET) return;
    s->work += cost;
    steps_before = ga2d_world_get_counters(s->w).step_count;
    failures = s->alloc.failures;
    r = ga2d_world_step(s->w, dt);
    FW_TRACE((stderr, "step %g: %s\n", (double)dt, ga2d_result_string(r)));
    FUZZ_CHECK((int)r >= 0 && r < GA2D_RESULT_COUNT);
    if (!(fz_finite((double)dt) && dt > 0)) FUZZ_CHECK(r == GA2D_ERR_INVALID_ARGUMENT);
    if (r == GA2D_ERR_INVALID_ARGUMENT) {
        /* refused: dt not finite and > 0, or too small to split */
        FUZZ_CHECK(!(fz_finite((double)dt) && dt > 0) || !(dt / (ga2d_real)s->substeps > 0));
        FUZZ_CHECK(ga2d_world_get_counters(s->w).step_count == steps_before);
        return;
    }
    if (r == GA2D_ERR_TOO_LARGE) {
        /* refused: beyond the step's bounds, and nothing changed */
        FUZZ_CHECK(fw_step_too_large(s, (double)dt, 0.999));
        FUZZ_CHECK(ga2d_world_get_counters(s->w).step_count == steps_before);
        return;
    }
    FUZZ_CHECK(!fw_step_too_large(s, (double)dt, 1.001));
    FUZZ_CHECK(ga2d_world_get_counters(s->w).step_count == steps_before + 1);
    fw_check_step(s, r, failures);
}

/* -------------------------------------------------------------- queries */
static void fw_draw_polygon(ga2d_body_id id, const ga2d_polygon *p, ga2d_transform x, uint32_t color, void *ctx)
{
    (void)id; (void)x; (void)color; (void)ctx;
    FUZZ_CHECK(p != NULL && p->count >= 3 && p->count <= GA2D_MAX_POLYGON_VERTICES);
}
static void fw_draw_segment(ga2d_vec a, ga2d_vec b, uint32_t color, void *ctx) { (void)a; (void)b; (void)color; (void)ctx; }
static void fw_draw_point(ga2d_vec p, ga2d_real size, uint32_t color, void *ctx) { (void)p; (void)size; (void)color; (void)ctx; }
static void fw_draw_contact(ga2d_vec p, ga2d_vec n, ga2d_real sep, uint32_t color, void *ctx)
{
    (void)p; (void)n; (void)sep; (void)color; (void)ctx;
}
static void fw_draw_aabb(ga2d_aabb b, uint32_t color, void *ctx) { (void)b; (void)color; (void)ctx; }

static void fw_queries(fw_state *s)
{
    ga2d_contact_data buf[8];
    ga2d_contact_events e = ga2d_world_contact_events(s->w);
    ga2d_debug_draw dd = ga2d_default_debug_draw();
    int n, i, k;
    FUZZ_CHECK(e.begin_count >= 0 && e.end_count >= 0);
    for (i = 0; i < e.begin_count; ++i) FUZZ_CHECK(e.begin[i].manifold.count >= 1 && e.begin[i].manifold.count <= 2);
    for (i = 0; i < e.end_count; ++i) FUZZ_CHECK(e.end[i].manifold.count >= 0 && e.end[i].manifold.count <= 2);
    n = ga2d_world_get_pairs(s->w, buf, 8);
    FUZZ_CHECK(n >= 0);
    n = ga2d_world_get_contacts(s->w, buf, 8);
    FUZZ_CHECK(n >= 0);
    for (i = 0; i < (n < 8 ? n : 8); ++i) {
        FUZZ_CHECK(buf[i].manifold.count >= 1 && buf[i].manifold.count <= 2);
        /* contacts join shapes, A's slot before B's, of two bodies */
        FUZZ_CHECK(buf[i].shape_a.index1 < buf[i].shape_b.index1 && buf[i].body_a.index1 != buf[i].body_b.index1);
    }
    for (k = 0; k < s->nids; ++k) {
        n = ga2d_body_get_contacts(s->w, s->ids[k], buf, 8);
        FUZZ_CHECK(n >= 0 && (n == 0 || ga2d_body_is_valid(s->w, s->ids[k])));
        (void)ga2d_body_kinetic_energy(s->w, s->ids[k]);
        (void)ga2d_body_velocity_at(s->w, s->ids[k], ga2d_vec_make(1, 2));
        (void)ga2d_body_angle(s->w, s->ids[k]);
        (void)ga2d_body_transform(s->w, s->ids[k]);
    }
    dd.polygon = fw_draw_polygon;
    dd.segment = fw_draw_segment;
    dd.point = fw_draw_point;
    dd.contact = fw_draw_contact;
    dd.aabb = fw_draw_aabb;
    dd.draw_contacts = dd.draw_aabbs = dd.draw_centers = 1;
    FUZZ_CHECK(ga2d_world_draw(s->w, &dd) == GA2D_OK);
    FUZZ_CHECK(ga2d_world_draw(s->w, NULL) == GA2D_ERR_INVALID_ARGUMENT);
    fw_check_counts(s);
}

/* ------------------------------------------------------- body setters */
static void fw_body_op(fw_state *s, int op)
{
    ga2d_body_id id = fw_id(s);
    int wild = fz_u8(&s->rd) < 32, valid = ga2d_body_is_valid(s->w, id);
    int type = (int)ga2d_body_get_type(s->w, id);
    fw_snap before, after;
    ga2d_result r = GA2D_OK;
    int changes = 1; /* a refused call must leave the body as it was */
    fw_take(s->w, id, &before);
    switch (op) {
    case 0: {
        ga2d_vec p = fw_vec(s, 4, wild);
        ga2d_rotor q = ga2d_rotor_from_angle(fw_val(s, 4, 0));
        if (wild) {
            q.c = fz_real(&s->rd, 1);
            q.s = fz_real(&s->rd, 1);
        }
        r = ga2d_body_set_transform(s->w, id, p, q);
        if (valid && !(fz_finite_vec(p) && fw_rotor_ok(q))) FUZZ_CHECK(r == GA2D_ERR_NOT_FINITE);
        if (r == GA2D_OK) {
            /* normalized: each component divided by the (scaled, ~2 eps)
               length, then rounded (eps/2): 4 eps */
            ga2d_rotor g = ga2d_body_rotor(s->w, id);
            FUZZ_CHECK(fabs(hypot((double)g.c, (double)g.s) - 1) <= 4 * FZ_EPS);
        }
        break;
    }
    case 1: {
        ga2d_vec v = fw_vec(s, 8, wild);
        r = ga2d_body_set_velocity(s->w, id, v);
        if (valid && !fz_finite_vec(v)) FUZZ_CHECK(r == GA2D_ERR_NOT_FINITE);
        else if (valid && type == GA2D_BODY_STATIC) FUZZ_CHECK(r == GA2D_ERR_INVALID_ARGUMENT);
        else if (valid) {
            ga2d_vec got = ga2d_body_velocity(s->w, id);
            FUZZ_CHECK(r == GA2D_OK && got.x == v.x && got.y == v.y);
        }
        break;
    }
    case 2:
        r = ga2d_body_set_angular_velocity(s->w, id, fw_val(s, 8, wild));
        break;
    case 3: {
        ga2d_mass m;
        m.mass = fw_pos(s, 4, wild);
        m.inertia = fw_pos(s, 4, wild);
        m.center = fw_vec(s, 1, wild);
        r = ga2d_body_set_mass_data(s->w, id, m);
        FW_TRACE((stderr, "set_mass_data m %g I %g c (%g %g): %s\n", (double)m.mass, (double)m.inertia, (double)m.center.x,
                  (double)m.center.y, ga2d_result_string(r)));
        if (valid && type != GA2D_BODY_DYNAMIC && fz_finite((double)m.mass) && fz_finite((double)m.inertia) &&
            fz_finite_vec(m.center))
            FUZZ_CHECK(r == GA2D_ERR_INVALID_ARGUMENT);
        break;
    }
    case 4:
        r = ga2d_body_set_gravity_scale(s->w, id, fw_val(s, 2, wild));
        break;
    case 5: {
        ga2d_real lin = fw_pos(s, 1, wild); /* one read a statement: see fw_polygon */
        r = ga2d_body_set_damping(s->w, id, lin, fw_pos(s, 1, wild));
        break;
    }
    case 6: {
        ga2d_filter f;
        f.category_bits = fz_u32(&s->rd);
        f.mask_bits = fz_u8(&s->rd) < 128 ? 0xFFFFFFFFu : fz_u32(&s->rd);
        f.group_index = (int32_t)(int8_t)fz_u8(&s->rd);
        r = ga2d_body_set_filter(s->w, id, f);
        break;
    }
    case 7:
        r = ga2d_body_set_awake(s->w, id, fz_u8(&s->rd) & 1);
        changes = 0; /* sleeping zeroes velocities; not checked here */
        break;
    case 8: {
        ga2d_vec f = fw_vec(s, 100, wild);
        r = ga2d_body_apply_force(s->w, id, f, fw_vec(s, 4, wild));
        changes = 0; /* forces are pending state no getter shows; a wake may happen */
        break;
    }
    case 9:
        r = ga2d_body_apply_force_to_center(s->w, id, fw_vec(s, 100, wild));
        changes = 0;
        break;
    case 10:
        r = ga2d_body_apply_torque(s->w, id, fw_val(s, 100, wild));
        changes = 0;
        break;
    case 11: {
        ga2d_vec imp = fw_vec(s, 10, wild);
        r = ga2d_body_apply_impulse(s->w, id, imp, fw_vec(s, 4, wild));
        break;
    }
    case 12:
        r = ga2d_body_apply_angular_impulse(s->w, id, fw_val(s, 10, wild));
        break;
    case 13: {
        int before_count;
        if (s->before_destroy) s->before_destroy(s, id);
        before_count = ga2d_world_get_counters(s->w).body_count;
        r = ga2d_body_destroy(s->w, id);
        FUZZ_CHECK(ga2d_world_get_counters(s->w).body_count == before_count - (r == GA2D_OK));
        if (r == GA2D_OK) FUZZ_CHECK(!ga2d_body_is_valid(s->w, id));
        changes = 0;
        break;
    }
    default:
        r = ga2d_body_set_user_data(s->w, id, fz_u8(&s->rd) & 1 ? NULL : &s->tag);
        break;
    }
    FW_TRACE((stderr, "body op %d on %u: %s\n", op, id.index1, ga2d_result_string(r)));
    FUZZ_CHECK((int)r >= 0 && r < GA2D_RESULT_COUNT);
    if (!valid) FUZZ_CHECK(r == GA2D_ERR_STALE_ID);
    if (r != GA2D_OK && changes) {
        fw_take(s->w, id, &after);
        FUZZ_CHECK(memcmp(&before, &after, sizeof before) == 0);
    }
}

/* ------------------------------------------------------- world setters */
static void fw_world_op(fw_state *s, int op)
{
    ga2d_result r;
    int k = fz_u8(&s->rd);
    FW_TRACE((stderr, "world op %d (%d)\n", op, k));
    switch (op) {
    case 0: {
        int wild = k < 40;
        ga2d_vec g = fw_vec(s, 20, wild);
        r = ga2d_world_set_gravity(s->w, g);
        if (!fz_finite_vec(g)) FUZZ_CHECK(r == GA2D_ERR_NOT_FINITE);
        else FUZZ_CHECK(r == (hypot((double)g.x, (double)g.y) > fw_max_gravity(s) ? GA2D_ERR_TOO_LARGE : GA2D_OK));
        if (r == GA2D_OK) FUZZ_CHECK(ga2d_world_gravity(s->w).x == g.x && ga2d_world_gravity(s->w).y == g.y);
        break;
    }
    case 1: {
        int n = k < 200 ? 1 + k % 8 : (k < 250 ? (int)fz_u16(&s->rd) % 1100 : -(int)(k - 249));
        r = ga2d_world_set_substeps(s->w, n);
        FUZZ_CHECK(r == ((n >= 1 && n <= 1024) ? GA2D_OK : GA2D_ERR_INVALID_ARGUMENT));
        if (r == GA2D_OK) s->substeps = n;
        break;
    }
    case 2: {
        int m = k % (GA2D_INTEGRATOR_COUNT + 1);
        long failures = s->alloc.failures;
        r = ga2d_world_set_integrator(s->w, (ga2d_integrator)m);
        if (m == GA2D_INTEGRATOR_COUNT) FUZZ_CHECK(r == GA2D_ERR_INVALID_ARGUMENT);
        else FUZZ_CHECK(r == (s->alloc.failures != failures ? GA2D_ERR_OUT_OF_MEMORY : GA2D_OK));
        if (r == GA2D_OK) s->rk4 = m == GA2D_INTEGRATOR_RK4;
        break;
    }
    case 3: {
        int m = k % (GA2D_ROTATION_COUNT + 1);
        r = ga2d_world_set_rotation_update(s->w, (ga2d_rotation_update)m);
        FUZZ_CHECK(r == (m == GA2D_ROTATION_COUNT ? GA2D_ERR_INVALID_ARGUMENT : GA2D_OK));
        break;
    }
    case 4: {
        int m = k % (GA2D_SOLVER_COUNT + 1);
        r = ga2d_world_set_solver(s->w, (ga2d_solver)m);
        FUZZ_CHECK(r == (m == GA2D_SOLVER_COUNT ? GA2D_ERR_INVALID_ARGUMENT : GA2D_OK));
        break;
    }
    case 5: {
        int on = (k >> 2) & 1;
        switch (k & 3) {
        case 0: r = ga2d_world_enable_sleep(s->w, on); break;
        case 1: r = ga2d_world_enable_warm_starting(s->w, on); break;
        case 2: r = ga2d_world_enable_friction(s->w, on); break;
        default: r = ga2d_world_enable_restitution(s->w, on); break;
        }
        FUZZ_CHECK(r == GA2D_OK);
        break;
    }
    case 6: {
        /* compaction gives memory back; only an allocation can fail it */
        long failures = s->alloc.failures;
        r = ga2d_world_compact(s->w);
        FUZZ_CHECK(r == GA2D_OK || r == GA2D_ERR_OUT_OF_MEMORY);
        FUZZ_CHECK((r == GA2D_ERR_OUT_OF_MEMORY) == (s->alloc.failures != failures));
        fw_check_counts(s);
        break;
    }
    default:
        s->field_kind = k % 3;
        s->field_forbidden = (k >> 2) & 1;
        s->field_k = fw_val(s, 20, (k >> 3) == 0);
        r = ga2d_world_set_force_callback(s->w, (k >> 4) & 1 ? fw_field : NULL, s);
        FUZZ_CHECK(r == GA2D_OK);
        break;
    }
}

/* --------------------------------------------------------------- world */
/* A task system that runs each stage's ranges itself, last first, at the
   least range the step allows (the step's results must not change), and
   checks that the world refuses a change from inside it. */
static void *fw_enqueue(ga2d_task_fn *task, int count, int min_range, void *context, void *user)
{
    fw_state *s = (fw_state *)user;
    int range = min_range < 1 ? 1 : min_range, k;
    if (s->w) FUZZ_CHECK(ga2d_world_set_gravity(s->w, ga2d_vec_make(0, 0)) == GA2D_ERR_LOCKED);
    for (k = (count + range - 1) / range - 1; k >= 0; --k)
        task(k * range, count - k * range > range ? k * range + range : count, k % 2, context);
    return s;
}

static void fw_finish(void *task, void *user) { FUZZ_CHECK(task == user); }

static ga2d_world_def fw_world_def(fw_state *s)
{
    ga2d_world_def d = ga2d_default_world_def();
    unsigned flags = fz_u8(&s->rd), k;
    int wild = (flags & 3) == 0;
    if (flags & 4) d.gravity = fw_vec(s, 20, wild);
    k = fz_u8(&s->rd);
    d.substeps = k < 200 ? (int)(k % 9) : (int)fz_u16(&s->rd) % 1100 - 20;
    d.integrator = (ga2d_integrator)fz_pick(&s->rd, GA2D_INTEGRATOR_COUNT + 1);
    d.rotation_update = (ga2d_rotation_update)fz_pick(&s->rd, GA2D_ROTATION_COUNT + 1);
    d.solver = (ga2d_solver)fz_pick(&s->rd, GA2D_SOLVER_COUNT + 1);
    if (flags & 8) {
        d.velocity_iterations = (int)(int8_t)fz_u8(&s->rd);
        d.position_iterations = (int)(int8_t)fz_u8(&s->rd);
    }
    if (flags & 16) {
        d.contact_hertz = fw_pos(s, 60, wild);
        d.contact_damping_ratio = fw_pos(s, 10, wild);
        d.contact_push_max_velocity = fw_pos(s, 2, wild);
        d.restitution_threshold = fw_pos(s, 2, wild);
    }
    if (flags & 32) d.length_units_per_meter = wild ? fz_real_pos(&s->rd, 1) : fz_narrow((double)(1 + fz_u8(&s->rd)) / 16);
    k = fz_u8(&s->rd);
    d.enable_sleep = (int)(k & 1);
    d.enable_warm_starting = (int)((k >> 1) & 1);
    d.enable_friction = (int)((k >> 2) & 1);
    d.enable_restitution = (int)((k >> 3) & 1);
    if (k & 16) d.internal_cookie = 0; /* hand-made: its zeros are the defaults */
    if (k & 32) { /* a task system (no byte read: older inputs step as they did) */
        d.worker_count = 1 + (int)(k >> 6);
        d.enqueue_task = fw_enqueue;
        d.finish_task = fw_finish;
        d.user_task_context = s;
    }
    if (flags & 64) {
        /* an allocator that fails: attempt k, and maybe every j-th after */
        s->alloc.fail_at = 1 + fz_u8(&s->rd);
        s->alloc.fail_every = fz_u8(&s->rd) < 128 ? 0 : 2 + fz_u8(&s->rd) % 16;
    }
    fz_alloc_attach(&s->alloc, &d);
    if (flags & 128) {
        s->field_kind = fz_pick(&s->rd, 3);
        s->field_forbidden = fz_u8(&s->rd) & 1;
        s->field_k = fw_val(s, 20, wild);
        d.force_callback = fw_field;
        d.force_context = s;
    }
    return d;
}

static int fuzz_world_one(const uint8_t *data, size_t size)
{
    fw_state s;
    ga2d_world_def d;
    ga2d_result valid;
    int i, n, ops = 0;
    memset(&s, 0, sizeof s);
    fz_init(&s.rd, data, size);
    d = fw_world_def(&s);
    valid = ga2d_world_def_validate(&d);
    s.w = ga2d_world_create(&d);
    FW_TRACE((stderr, "world: g (%g %g) substeps %d integrator %d rotation %d solver %d iters %d/%d hz %g zeta %g push %g thr %g units %g switches %d%d%d%d fail_at %ld/%ld field %d: %s\n",
              (double)d.gravity.x, (double)d.gravity.y, d.substeps, (int)d.integrator, (int)d.rotation_update, (int)d.solver,
              d.velocity_iterations, d.position_iterations, (double)d.contact_hertz, (double)d.contact_damping_ratio,
              (double)d.contact_push_max_velocity, (double)d.restitution_threshold, (double)d.length_units_per_meter,
              d.enable_sleep, d.enable_warm_starting, d.enable_friction, d.enable_restitution, s.alloc.fail_at,
              s.alloc.fail_every, d.force_callback != NULL, ga2d_result_string(valid)));
    FW_TRACE((stderr, "field kind %d k %g forbidden %d\n", s.field_kind, (double)s.field_k, s.field_forbidden));
    if (!s.w) {
        FUZZ_CHECK(valid != GA2D_OK || s.alloc.failures > 0);
        FUZZ_CHECK(s.alloc.live_bytes == 0 && s.alloc.live_blocks == 0);
        return 0;
    }
    FUZZ_CHECK(valid == GA2D_OK);
    s.substeps = d.substeps ? d.substeps : 4;
    s.units = d.length_units_per_meter > 0 ? (double)d.length_units_per_meter : 1;
    s.passes = d.solver == GA2D_SOLVER_SOFT_STEP ? 2
               : (d.velocity_iterations ? d.velocity_iterations : 8) + (d.position_iterations ? d.position_iterations : 3);
    if (s.passes < 2) s.passes = 2;
    s.rk4 = d.integrator == GA2D_INTEGRATOR_RK4;

    n = fz_pick(&s.rd, 24);
    for (i = 0; i < n; ++i) fw_create(&s);
    fw_check_counts(&s);

    while (fz_more(&s.rd) && ops++ < FW_MAX_OPS) {
        int op = fz_pick(&s.rd, 32);
        if (op < 10) fw_step(&s);
        else if (op < 13) fw_create(&s);
        else if (op < 28) fw_body_op(&s, op - 13);
        else if (op < 31) fw_world_op(&s, fz_pick(&s.rd, 8));
        else fw_queries(&s);
    }
    /* always end with a couple of ordinary steps and the queries */
    for (i = 0; i < 2; ++i) {
        long cost = (long)s.substeps * s.passes * (s.rk4 ? 4 : 1) * (ga2d_world_get_counters(s.w).body_count + 1);
        long failures = s.alloc.failures;
        ga2d_result r;
        if (s.work + cost > FW_WORK_BUDGET) break;
        s.work += cost;
        r = ga2d_world_step(s.w, (ga2d_real)(1.0 / 60));
        FW_TRACE((stderr, "final step: %s\n", ga2d_result_string(r)));
        if (r == GA2D_ERR_INVALID_ARGUMENT) FUZZ_CHECK(!((ga2d_real)(1.0 / 60) / (ga2d_real)s.substeps > 0));
        else if (r == GA2D_ERR_TOO_LARGE) FUZZ_CHECK(fw_step_too_large(&s, (double)(ga2d_real)(1.0 / 60), 0.999));
        else fw_check_step(&s, r, failures);
    }
    fw_queries(&s);
    ga2d_world_destroy(s.w);
    /* every byte back, each block freed with its own size */
    FUZZ_CHECK(s.alloc.live_bytes == 0 && s.alloc.live_blocks == 0);
    return 0;
}

#endif
