/* Re-entry fuzzing: every public call that takes a world or a body id, made
   from inside every callback the library makes, on the SAME world, with
   random ids (live, destroyed, forged, null, out of range) and random
   arguments (ordinary, NaN, infinities, huge).

   The callbacks: the force callback (during ga2d_world_step), the five
   debug-draw callbacks (during ga2d_world_draw, every switch on) and the
   allocator's alloc and free (during any call that allocates, and
   ga2d_world_destroy).  The input builds a small world (random def knobs
   within their valid ranges, static ground, a few dynamic boxes and
   polygons, a counting allocator that may be told to fail, maybe a force
   field), then runs a sequence of outer operations: steps, draws, body
   creation and destruction, snapshot save and load, body and world
   setters, compaction, the integrator switch (RK4 allocates), joint
   makers (each kind; the pool grows through the allocator), joint
   destroys and setters, and ga2d_world_destroy.  In each callback the input picks up to
   FR_MAX_CALLS calls from the whole API (see fr_call), ga2d_world_destroy
   among them.  A world destroyed from a callback is freed when the outer
   call returns; the harness then builds another from the rest of the
   input (up to FR_MAX_WORLDS).

   What is checked (the header's ERRORS section, "Calls from inside the
   library's callbacks"):
     - no crash, no sanitizer report, no leak: the counting allocator has
       every byte back once a world is gone, each block freed with its size;
     - from any callback every call that would change the world returns
       GA2D_ERR_LOCKED (INVALID_ARGUMENT is also taken where the harness
       passed a NULL pointer; ga2d_body_create returns the null id), except
       ga2d_body_apply_force, _apply_force_to_center and _apply_torque from
       the force callback, which follow their normal rules (STALE_ID,
       NOT_FINITE, OK);
     - every call made from a callback changes nothing a getter can see:
       the target body's state, the world's counters, time, gravity,
       snapshot size, pairs, events and error body, bit for bit; no call
       made from a callback calls back;
     - ga2d_world_destroy from a callback: the world still reads (and
       refuses changes) until the outer call returns; the outer call
       returns a valid result; no force or draw callback comes after the
       request (FR_LENIENT_DRAW: the body or contact being drawn may still
       finish, as ga2d_world_draw's comment has it); the world is freed
       when the outer call returns (live bytes 0) and never used again;
       from a free hook of the world's own destruction the world reads as
       empty;
     - joints from a callback: every maker (each kind, any def, a NULL
       one) answers LOCKED (INVALID_ARGUMENT for NULL) with the null id,
       ga2d_joint_destroy and every setter LOCKED, and nothing changes
       (the joint count and snapshot size with the rest); the joint
       getters read a live joint's bodies live and its readings finite, a
       stale id zero; a draw calls the segment callback three times a
       joint; an outer joint call refused leaves the world's bytes as they
       were, and with the twin on, the same call there answers the same
       and leaves the same world;
     - getters read finite values for every live id, at every callback;
       the body count seen from a callback is the count of the live ids
       the harness made;
     - the outer call's result is what the outer call alone would give:
       the body count and every id's validity do not change through a
       draw or a step; a draw leaves the world's snapshot bit for bit as it
       was and calls back once per body (polygon, box, centre) and once
       per contact point; and, when the input turns on the twin check, a
       second world loaded with the same snapshot and given the same outer
       call (step, create, save, load, compact, integrator; its force
       field replays the forces the first world's field applied, and must
       get the same results back) ends in the same state: the same
       snapshot bytes or, where they differ, the same everything the
       getters see (every id, counters, time, pairs with their manifolds
       and impulses, error body, and after a step the events).  A call
       refused (bad argument, out of memory) leaves the world's snapshot
       bit for bit as it was.

   Knobs (compile-time):
     FR_LENIENT_DRAW     accept the draw callbacks of the body or contact
                         being drawn when a callback asked to destroy the
                         world (ga2d_world_draw's own comment: "ends the
                         drawing at the next body"); by default none may
                         come (the ERRORS section: "finishes without
                         calling back again").
     FR_STRICT_ALLOC     also refuse allocations after a destroy request
                         in the same call (the same ERRORS sentence; the
                         call under way still allocates what it needs).
     FR_LENIENT_FIELD_STATE  accept a live body's state read as not
                         finite from the force callback (RK4 evaluates the
                         field at stage states that a huge but accepted
                         force overflowed; the step contains the body only
                         after the substep).
     FR_LENIENT_STATIC_VELOCITY  accept a static body's velocity read as
                         NaN (a step that contained a body can leave it
                         there).
     FR_STRICT_SNAPSHOT  the twin check on snapshot bytes alone, after a
                         load-and-save into a third world (which renumbers
                         tree leaves and scratch fields): a snapshot also
                         carries the unused points of non-touching
                         manifolds as the library left them. */
#ifndef GA2D_FUZZ_REENTRY_H
#define GA2D_FUZZ_REENTRY_H

#include "fuzz_common.h"

#define FR_MAX_IDS 32
#define FR_MAX_OPS 48
#define FR_MAX_CALLS 8 /* calls per callback */
#define FR_MAX_WORLDS 3
#define FR_MAX_LOG 2048 /* force calls per step, for the twin's replay */
#define FR_WORK_BUDGET 250000L
#define FR_SCRATCH 512
#define FR_MAX_JOINTS 32

#ifdef FUZZ_VERBOSE
#define FR_TRACE(args) (fprintf args)
#else
#define FR_TRACE(args) ((void)0)
#endif

/* who calls back */
enum { FR_CB_FORCE, FR_CB_POLYGON, FR_CB_SEGMENT, FR_CB_POINT, FR_CB_CONTACT, FR_CB_AABB, FR_CB_ALLOC, FR_CB_FREE, FR_CB_COUNT };
/* the library call under way */
enum {
    FR_OP_NONE,
    FR_OP_STEP,
    FR_OP_DRAW,
    FR_OP_CREATE,
    FR_OP_BODY,
    FR_OP_SAVE,
    FR_OP_LOAD,
    FR_OP_WORLD,
    FR_OP_DESTROY,
    FR_OP_JOINT
};

typedef struct fr_buf { unsigned char *p; size_t n, cap; } fr_buf;

/* a force-type call made from the force callback, replayed in the twin */
typedef struct fr_force_call {
    int eval, kind;
    ga2d_body_id id;
    ga2d_vec f, p;
    ga2d_real t;
    ga2d_result r;
} fr_force_call;

typedef struct fr_state {
    fz_reader rd;
    ga2d_world *w; /* NULL once freed */
    fz_alloc alloc;
    int quiet;     /* the harness's own calls: hooks neither call in nor fail */
    int worlds;
    /* the outer call */
    int outer, cb_depth, cb, destroy_requested, destroy_cb;
    int cb_count[FR_CB_COUNT], after_destroy[FR_CB_COUNT];
    int count_before;
    long failures_before;
    unsigned char valid_before[FR_MAX_IDS];
    /* every id the harness made (all bodies there are) */
    ga2d_body_id ids[FR_MAX_IDS];
    int nids;
    /* every joint id the harness made */
    ga2d_joint_id jids[FR_MAX_JOINTS];
    int njids;
    int field_on, substeps, rk4;
    long work;
    /* the twin */
    int twin_on, twin_ready, twin_evals, replay_at, nlog, log_full;
    ga2d_world *twin, *canon; /* canon: where snapshots are put in canonical form */
    fz_alloc twin_alloc;
    fr_force_call log[FR_MAX_LOG];
    fr_buf before, after_a, after_b, slot[2], tmp;
    unsigned char scratch[FR_SCRATCH];
    ga2d_contact_data cbuf[8];
    ga2d_debug_draw dd;
    int tag;
} fr_state;

/* --------------------------------------------------------------- values */
static int fr_reserve(fr_buf *b, size_t n)
{
    if (n > b->cap) {
        unsigned char *p = (unsigned char *)realloc(b->p, n);
        if (!p) return 0;
        b->p = p;
        b->cap = n;
    }
    return 1;
}

/* an ordinary value, k/16 * scale */
static ga2d_real fr_small(fr_state *s, double scale) { return fz_narrow((double)(int8_t)fz_u8(&s->rd) * scale / 16); }
static ga2d_vec fr_vec(fr_state *s, double scale, int wild)
{
    ga2d_vec v;
    v.x = wild ? fz_real(&s->rd, scale) : fr_small(s, scale);
    v.y = wild ? fz_real(&s->rd, scale) : fr_small(s, scale);
    return v;
}

/* A tracked id (live or destroyed), the null id, a forged one, one out of
   range, or a tracked one with its generation off by one. */
static ga2d_body_id fr_id(fr_state *s)
{
    unsigned k = fz_u8(&s->rd);
    ga2d_body_id id = ga2d_body_id_null();
    if (s->nids > 0 && k < 200) return s->ids[k % (unsigned)s->nids];
    if (k < 215) return id;
    if (k < 230) {
        id.index1 = 1 + fz_u8(&s->rd) % 64;
        id.generation = fz_u32(&s->rd);
    } else if (k < 240) {
        id.index1 = (k & 1) ? 0xFFFFFFFFu : 0x80000000u;
        id.generation = fz_u32(&s->rd);
    } else if (s->nids > 0) {
        id = s->ids[fz_u8(&s->rd) % (unsigned)s->nids];
        id.generation += (k & 1) ? 1u : 0xFFFFFFFFu;
    }
    return id;
}

static int fr_finite_rotor(ga2d_rotor q) { return fz_finite((double)q.c) && fz_finite((double)q.s); }
static void fr_check_joint(const fr_state *s, ga2d_joint_id id);

/* ------------------------------------------------------ what is seen */
/* Everything the getters say about one body. */
typedef struct fr_body {
    int valid, type, awake, contacts;
    ga2d_vec position, center, velocity, vel_at;
    ga2d_rotor q;
    ga2d_real angle, w, ke;
    ga2d_transform x;
    ga2d_mass mass;
    ga2d_filter filter;
    void *user;
    ga2d_aabb fat;
    int has_poly;
    ga2d_polygon poly;
} fr_body;

static void fr_take_body(const ga2d_world *w, ga2d_body_id id, fr_body *o)
{
    const ga2d_polygon *p;
    memset(o, 0, sizeof *o);
    o->valid = ga2d_body_is_valid(w, id);
    o->type = (int)ga2d_body_get_type(w, id);
    o->awake = ga2d_body_is_awake(w, id);
    o->contacts = ga2d_body_get_contacts(w, id, NULL, 0);
    o->position = ga2d_body_position(w, id);
    o->center = ga2d_body_center(w, id);
    o->velocity = ga2d_body_velocity(w, id);
    o->vel_at = ga2d_body_velocity_at(w, id, o->center);
    o->q = ga2d_body_rotor(w, id);
    o->angle = ga2d_body_angle(w, id);
    o->w = ga2d_body_angular_velocity(w, id);
    o->ke = ga2d_body_kinetic_energy(w, id);
    o->x = ga2d_body_transform(w, id);
    o->mass = ga2d_body_mass_data(w, id);
    o->filter = ga2d_body_filter(w, id);
    o->user = ga2d_body_user_data(w, id);
    o->fat = ga2d_body_fat_aabb(w, id);
    p = ga2d_body_polygon(w, id);
    o->has_poly = p != NULL;
    if (p) o->poly = *p;
}

/* What a getter reports of a live body is finite. */
static void fr_check_live(const fr_state *s, const fr_body *b)
{
    int i;
    FUZZ_CHECK(b->type >= 0 && b->type < GA2D_BODY_TYPE_COUNT);
    FUZZ_CHECK(b->awake == 0 || b->awake == 1);
    FUZZ_CHECK(b->contacts >= 0);
#ifdef FR_LENIENT_FIELD_STATE
    if (!(s->cb_depth && s->cb == FR_CB_FORCE))
#endif
    {
        int motion = 1; /* velocities, and what is made of them */
#ifdef FR_LENIENT_STATIC_VELOCITY
        motion = b->type != GA2D_BODY_STATIC;
#endif
        FUZZ_CHECK(fz_finite_vec(b->position) && fz_finite_vec(b->center));
        FUZZ_CHECK(fr_finite_rotor(b->q) && fabs(hypot((double)b->q.c, (double)b->q.s) - 1) < 1e-3);
        FUZZ_CHECK(fz_finite((double)b->angle));
        FUZZ_CHECK(fz_finite_vec(b->x.p) && fr_finite_rotor(b->x.q));
        if (motion) {
            FUZZ_CHECK(fz_finite_vec(b->velocity) && fz_finite_vec(b->vel_at) && fz_finite((double)b->w));
            FUZZ_CHECK(!(b->ke != b->ke) && !(b->ke < 0));
        }
    }
    FUZZ_CHECK(fz_finite((double)b->mass.mass) && fz_finite_vec(b->mass.center) && fz_finite((double)b->mass.inertia));
    FUZZ_CHECK(b->mass.mass >= 0 && b->mass.inertia >= 0);
    FUZZ_CHECK(fz_finite_vec(b->fat.lower) && fz_finite_vec(b->fat.upper));
    FUZZ_CHECK(b->fat.lower.x <= b->fat.upper.x && b->fat.lower.y <= b->fat.upper.y);
    FUZZ_CHECK(b->has_poly && b->poly.count >= 3 && b->poly.count <= GA2D_MAX_POLYGON_VERTICES);
    for (i = 0; i < b->poly.count && i < GA2D_MAX_POLYGON_VERTICES; ++i)
        FUZZ_CHECK(fz_finite_vec(b->poly.vertices[i]) && fz_finite_vec(b->poly.normals[i]));
    FUZZ_CHECK(b->user == NULL || b->user == (const void *)&s->tag);
}

/* What an id that names no body reads: zeros, the identity rotor. */
static void fr_check_dead(const fr_body *b)
{
    FUZZ_CHECK(b->type == 0 && b->awake == 0 && b->contacts == 0 && !b->has_poly && b->user == NULL);
    FUZZ_CHECK(b->position.x == 0 && b->position.y == 0 && b->velocity.x == 0 && b->velocity.y == 0);
    FUZZ_CHECK(b->q.c == 1 && b->q.s == 0 && b->w == 0 && b->mass.mass == 0);
}

/* Everything the getters say about the world. */
typedef struct fr_view {
    ga2d_world_counters c;
    double time;
    ga2d_vec g;
    size_t snap;
    int pairs, touching;
    ga2d_contact_events e;
    ga2d_body_id err;
} fr_view;

static void fr_take_view(const ga2d_world *w, fr_view *o)
{
    memset(o, 0, sizeof *o);
    o->c = ga2d_world_get_counters(w);
    o->time = ga2d_world_time(w);
    o->g = ga2d_world_gravity(w);
    o->snap = ga2d_world_snapshot_size(w);
    o->pairs = ga2d_world_get_pairs(w, NULL, 0);
    o->touching = ga2d_world_get_contacts(w, NULL, 0);
    o->e = ga2d_world_contact_events(w);
    o->err = ga2d_world_error_body(w);
}

/* the live bodies among the tracked ids (an id may be tracked twice when
   a new world reuses a freed one's address, and so its tag) */
static int fr_live_count(const fr_state *s)
{
    int i, j, n = 0;
    for (i = 0; i < s->nids; ++i) {
        if (!ga2d_body_is_valid(s->w, s->ids[i])) continue;
        for (j = 0; j < i; ++j)
            if (ga2d_body_id_equal(s->ids[i], s->ids[j])) break;
        n += j == i;
    }
    return n;
}

static void fr_check_contact_data(const fr_state *s, const ga2d_contact_data *c, int touching)
{
    FUZZ_CHECK(ga2d_body_is_valid(s->w, c->body_a) && ga2d_body_is_valid(s->w, c->body_b));
    /* contacts join two shapes of two bodies (the world lists A's shape
       slot first; a body's own list faces out of that body) */
    FUZZ_CHECK(c->shape_a.index1 != c->shape_b.index1 && c->body_a.index1 != c->body_b.index1);
    FUZZ_CHECK(c->manifold.count >= (touching ? 1 : 0) && c->manifold.count <= 2);
}

/* The world as a callback sees it: consistent, every live body finite. */
static void fr_check_world(fr_state *s)
{
    ga2d_world_counters c = ga2d_world_get_counters(s->w);
    int i, live = fr_live_count(s);
    FUZZ_CHECK(c.body_count == live);
    FUZZ_CHECK(c.moving_body_count >= 0 && c.moving_body_count <= c.body_count);
    FUZZ_CHECK(c.awake_body_count >= 0 && c.pair_count >= 0 && c.touching_count >= 0 && c.touching_count <= c.pair_count);
    FUZZ_CHECK(fz_finite(ga2d_world_time(s->w)) && fz_finite_vec(ga2d_world_gravity(s->w)));
    FUZZ_CHECK(c.joint_count >= 0 && c.joints_solved >= 0); /* joints_solved: the last step's */
    for (i = 0; i < s->njids; ++i) fr_check_joint(s, s->jids[i]);
    for (i = 0; i < s->nids; ++i) {
        fr_body b;
        fr_take_body(s->w, s->ids[i], &b);
        FR_TRACE((stderr, "  body %u: valid %d type %d awake %d c (%g %g) v (%g %g) q (%g %g) w %g m %g I %g\n", s->ids[i].index1,
                  b.valid, b.type, b.awake, (double)b.center.x, (double)b.center.y, (double)b.velocity.x, (double)b.velocity.y,
                  (double)b.q.c, (double)b.q.s, (double)b.w, (double)b.mass.mass, (double)b.mass.inertia));
        if (b.valid) fr_check_live(s, &b);
        else fr_check_dead(&b);
    }
}

/* --------------------------------------------------------------- joints */
/* A tracked joint id (live or not), the null id, a forged one, or a
   tracked one with its generation off by one. */
static ga2d_joint_id fr_jid(fr_state *s)
{
    unsigned k = fz_u8(&s->rd);
    ga2d_joint_id id = ga2d_joint_id_null();
    if (s->njids > 0 && k < 200) return s->jids[k % (unsigned)s->njids];
    if (k < 215) return id;
    if (k < 240 || s->njids == 0) {
        id.index1 = (k & 1) ? 0xFFFFFFFFu : 1 + fz_u8(&s->rd) % 16;
        id.generation = fz_u32(&s->rd);
    } else {
        id = s->jids[fz_u8(&s->rd) % (unsigned)s->njids];
        id.generation += (k & 1) ? 1u : 0xFFFFFFFFu;
    }
    return id;
}

/* One joint call, decoded before it is made, so that the twin gets the
   same: a maker (kind 0-3: revolute, distance, weld, motor), a destroy,
   or one of the 21 setters. */
typedef struct fr_jcall {
    int op; /* 0 make, 1 destroy, 2 set */
    int kind, which, flags, on, null_def;
    ga2d_body_id a, b;
    ga2d_joint_id id;
    ga2d_vec la, lb, v;
    ga2d_real x[6];
} fr_jcall;

static ga2d_real fr_jreal(fr_state *s, double scale, int wild) { return wild ? fz_real(&s->rd, scale) : fr_small(s, scale); }

static void fr_jcall_read(fr_state *s, fr_jcall *c, int op)
{
    unsigned k = fz_u8(&s->rd);
    int wild = k >= 208, i;
    memset(c, 0, sizeof *c);
    c->op = op;
    c->kind = (int)(k % 4);
    c->which = fz_pick(&s->rd, 21);
    c->flags = (int)fz_u8(&s->rd);
    c->on = (c->flags & 3) - 1;
    c->null_def = (c->flags & 0xF0) == 0xF0;
    c->a = fr_id(s);
    c->b = (c->flags & 0x1C) == 0 ? c->a : fr_id(s);
    c->id = fr_jid(s);
    c->la = fr_vec(s, 0.25, wild && (c->flags & 4));
    c->lb = fr_vec(s, 0.25, wild && (c->flags & 8));
    c->v = fr_vec(s, 1, wild);
    for (i = 0; i < 6; ++i) c->x[i] = fr_jreal(s, 1, wild && (fz_u8(&s->rd) & 1));
    /* mostly valid numbers: magnitudes where they must not be negative,
       limits in order */
    if (!wild) {
        for (i = 0; i < 6; ++i) c->x[i] = fz_narrow(fabs((double)c->x[i]));
        if (c->x[1] > c->x[2]) {
            ga2d_real t = c->x[1];
            c->x[1] = c->x[2];
            c->x[2] = t;
        }
        c->x[1] = -c->x[1];
        if (!(c->x[0] > 0)) c->x[0] = 1;
        if (c->x[3] > 1) c->x[3] = 1;
    }
}

/* Makes the call on world w: its result, *out the joint made. */
static ga2d_result fr_jcall_do(ga2d_world *w, const fr_jcall *c, ga2d_joint_id *out)
{
    const ga2d_real *x = c->x;
    ga2d_joint_id id = c->id;
    *out = ga2d_joint_id_null();
    if (c->op == 0) {
        switch (c->kind) {
        case 0: {
            ga2d_revolute_joint_def d = ga2d_default_revolute_joint_def();
            d.body_a = c->a, d.body_b = c->b, d.local_anchor_a = c->la, d.local_anchor_b = c->lb;
            d.collide_connected = (c->flags >> 5) & 1;
            d.enable_limit = (c->flags >> 6) & 1, d.enable_motor = c->flags >> 7, d.enable_spring = c->flags & 1;
            d.reference_angle = x[5], d.lower_angle = x[1], d.upper_angle = x[2];
            d.motor_speed = x[5], d.max_motor_torque = x[4], d.hertz = x[3], d.damping_ratio = x[0];
            return ga2d_revolute_joint_create_checked(w, c->null_def ? NULL : &d, out);
        }
        case 1: {
            ga2d_distance_joint_def d = ga2d_default_distance_joint_def();
            d.body_a = c->a, d.body_b = c->b, d.local_anchor_a = c->la, d.local_anchor_b = c->lb;
            d.collide_connected = (c->flags >> 5) & 1;
            d.length = x[0], d.enable_limit = (c->flags >> 6) & 1, d.min_length = -x[1], d.max_length = x[2];
            d.enable_spring = c->flags >> 7, d.hertz = x[3], d.damping_ratio = x[4];
            d.enable_motor = c->flags & 1, d.motor_speed = x[5], d.max_motor_force = x[4];
            return ga2d_distance_joint_create_checked(w, c->null_def ? NULL : &d, out);
        }
        case 2: {
            ga2d_weld_joint_def d = ga2d_default_weld_joint_def();
            d.body_a = c->a, d.body_b = c->b, d.local_anchor_a = c->la, d.local_anchor_b = c->lb;
            d.collide_connected = (c->flags >> 5) & 1;
            d.reference_angle = x[5], d.linear_hertz = (c->flags & 64) ? x[3] : 0, d.angular_hertz = (c->flags & 128) ? x[4] : 0;
            d.linear_damping_ratio = x[0], d.angular_damping_ratio = x[2];
            return ga2d_weld_joint_create_checked(w, c->null_def ? NULL : &d, out);
        }
        default: {
            ga2d_motor_joint_def d = ga2d_default_motor_joint_def();
            d.body_a = c->a, d.body_b = c->b, d.local_anchor_a = c->la, d.local_anchor_b = c->lb;
            d.collide_connected = (c->flags >> 5) & 1;
            d.linear_offset = c->v, d.angular_offset = x[5], d.max_force = x[4] * 100, d.max_torque = x[2] * 10;
            d.correction_factor = x[3];
            return ga2d_motor_joint_create_checked(w, c->null_def ? NULL : &d, out);
        }
        }
    }
    if (c->op == 1) return ga2d_joint_destroy(w, id);
    switch (c->which) {
    case 0: return ga2d_revolute_joint_enable_motor(w, id, c->on);
    case 1: return ga2d_revolute_joint_set_motor_speed(w, id, x[5]);
    case 2: return ga2d_revolute_joint_set_max_motor_torque(w, id, x[4]);
    case 3: return ga2d_revolute_joint_enable_limit(w, id, c->on);
    case 4: return ga2d_revolute_joint_set_limits(w, id, x[1], x[2]);
    case 5: return ga2d_revolute_joint_enable_spring(w, id, c->on);
    case 6: return ga2d_revolute_joint_set_spring(w, id, x[3], x[0]);
    case 7: return ga2d_distance_joint_set_length(w, id, x[0]);
    case 8: return ga2d_distance_joint_enable_limit(w, id, c->on);
    case 9: return ga2d_distance_joint_set_length_range(w, id, -x[1], x[2]);
    case 10: return ga2d_distance_joint_enable_spring(w, id, c->on);
    case 11: return ga2d_distance_joint_set_spring(w, id, x[3], x[4]);
    case 12: return ga2d_distance_joint_enable_motor(w, id, c->on);
    case 13: return ga2d_distance_joint_set_motor_speed(w, id, x[5]);
    case 14: return ga2d_distance_joint_set_max_motor_force(w, id, x[4]);
    case 15: return ga2d_weld_joint_set_linear_spring(w, id, x[3], x[0]);
    case 16: return ga2d_weld_joint_set_angular_spring(w, id, x[4], x[2]);
    case 17: return ga2d_motor_joint_set_linear_offset(w, id, c->v);
    case 18: return ga2d_motor_joint_set_angular_offset(w, id, x[5]);
    case 19: return ga2d_motor_joint_set_max_force(w, id, x[4]);
    default: return ga2d_motor_joint_set_max_torque(w, id, x[2]);
    }
}

/* What the getters say of a joint id: a live joint's bodies live, its
   readings finite where they must be; a stale id reads zero. */
static void fr_check_joint(const fr_state *s, ga2d_joint_id id)
{
    const ga2d_world *w = s->w;
    int valid = ga2d_joint_is_valid(w, id), type = (int)ga2d_joint_get_type(w, id);
    ga2d_body_id a = ga2d_joint_body_a(w, id), b = ga2d_joint_body_b(w, id);
    ga2d_vec f = ga2d_joint_reaction_force(w, id);
    ga2d_real t = ga2d_joint_reaction_torque(w, id), len = ga2d_distance_joint_current_length(w, id);
    ga2d_real angle = ga2d_revolute_joint_angle(w, id);
    if (!valid) {
        FUZZ_CHECK(type == GA2D_JOINT_TYPE_COUNT && ga2d_body_id_is_null(a) && ga2d_body_id_is_null(b));
        FUZZ_CHECK(f.x == 0 && f.y == 0 && t == 0 && len == 0 && angle == 0);
        FUZZ_CHECK(ga2d_revolute_joint_speed(w, id) == 0 && ga2d_revolute_joint_motor_torque(w, id) == 0);
        FUZZ_CHECK(ga2d_joint_user_data(w, id) == NULL && ga2d_joint_collide_connected(w, id) == 0);
        return;
    }
    FUZZ_CHECK(type >= 0 && type < GA2D_JOINT_TYPE_COUNT);
    FUZZ_CHECK(ga2d_body_is_valid(w, a) && ga2d_body_is_valid(w, b) && !ga2d_body_id_equal(a, b));
    FUZZ_CHECK(ga2d_body_get_type(w, a) == GA2D_BODY_DYNAMIC || ga2d_body_get_type(w, b) == GA2D_BODY_DYNAMIC);
    FUZZ_CHECK(fz_finite((double)angle) && fz_finite((double)len) && len >= 0);
    FUZZ_CHECK(ga2d_joint_user_data(w, id) == NULL);
}

static void fr_remember_joint(fr_state *s, ga2d_joint_id id)
{
    int i;
    for (i = 0; i < s->njids; ++i)
        if (ga2d_joint_id_equal(s->jids[i], id)) return;
    if (s->njids < FR_MAX_JOINTS) s->jids[s->njids++] = id;
}

/* ------------------------------------------------------ the callbacks */
static void fr_call(fr_state *s, int cb);

/* Every callback comes here: the checks, then the input's calls. */
static void fr_reenter(fr_state *s, int cb)
{
    int n, i;
    if (s->quiet || !s->w) return; /* the harness's own call, or the world not made yet */
    ++s->cb_count[cb];
    /* a call made from a callback never calls back */
    FUZZ_CHECK(s->cb_depth == 0);
    if (s->cb_depth) return;
    if (cb == FR_CB_FORCE) FUZZ_CHECK(s->outer == FR_OP_STEP);
    if (cb >= FR_CB_POLYGON && cb <= FR_CB_AABB) FUZZ_CHECK(s->outer == FR_OP_DRAW);
    if (s->destroy_requested) {
        /* no force or draw callback after a destroy request */
        int k = ++s->after_destroy[cb];
        FUZZ_CHECK(cb != FR_CB_FORCE);
#ifdef FR_LENIENT_DRAW
        /* the body (its box, its centre) or contact (its other point)
           being drawn when the request came may finish */
        if (cb == FR_CB_POLYGON) FUZZ_CHECK(!"polygon callback after a destroy request");
        if (cb == FR_CB_AABB || cb == FR_CB_POINT) FUZZ_CHECK(k == 1 && s->destroy_cb != FR_CB_CONTACT);
        if (cb == FR_CB_CONTACT) FUZZ_CHECK(k == 1 && s->destroy_cb == FR_CB_CONTACT);
#else
        FUZZ_CHECK(cb < FR_CB_POLYGON || cb > FR_CB_AABB);
#endif
#ifdef FR_STRICT_ALLOC
        FUZZ_CHECK(cb != FR_CB_ALLOC);
#endif
        (void)k;
    }
    s->cb_depth = 1;
    s->cb = cb;
    {
        /* the body count seen from a callback: the outer call's, or 0 once
           the world is being freed, or a loaded snapshot's */
        int count = ga2d_world_get_counters(s->w).body_count;
        if (s->outer != FR_OP_LOAD)
            FUZZ_CHECK(count == s->count_before ||
                       (count == 0 && (s->outer == FR_OP_DESTROY || s->destroy_requested) && cb == FR_CB_FREE));
    }
    if (fz_u8(&s->rd) & 1) fr_check_world(s);
    n = fz_pick(&s->rd, FR_MAX_CALLS + 1);
    for (i = 0; i < n; ++i) fr_call(s, cb);
    s->cb_depth = 0;
}

static void fr_force_field(ga2d_world *w, void *ctx)
{
    fr_state *s = (fr_state *)ctx;
    FUZZ_CHECK(w == s->w);
    fr_reenter(s, FR_CB_FORCE);
}

static void fr_draw_polygon(ga2d_body_id id, const ga2d_polygon *p, ga2d_transform x, uint32_t color, void *ctx)
{
    fr_state *s = (fr_state *)ctx;
    (void)color;
    FUZZ_CHECK(p != NULL && p->count >= 3 && p->count <= GA2D_MAX_POLYGON_VERTICES);
    FUZZ_CHECK(fz_finite_vec(x.p) && fr_finite_rotor(x.q));
    if (s->w) FUZZ_CHECK(ga2d_body_is_valid(s->w, id));
    fr_reenter(s, FR_CB_POLYGON);
}
static void fr_draw_segment(ga2d_vec a, ga2d_vec b, uint32_t color, void *ctx)
{
    (void)a; (void)b; (void)color;
    fr_reenter((fr_state *)ctx, FR_CB_SEGMENT);
}
static void fr_draw_point(ga2d_vec p, ga2d_real size, uint32_t color, void *ctx)
{
    (void)color;
    FUZZ_CHECK(fz_finite_vec(p) && size > 0);
    fr_reenter((fr_state *)ctx, FR_CB_POINT);
}
static void fr_draw_contact(ga2d_vec p, ga2d_vec n, ga2d_real sep, uint32_t color, void *ctx)
{
    (void)color;
    FUZZ_CHECK(fz_finite_vec(p) && fz_finite_vec(n) && fz_finite((double)sep));
    fr_reenter((fr_state *)ctx, FR_CB_CONTACT);
}
static void fr_draw_aabb(ga2d_aabb b, uint32_t color, void *ctx)
{
    (void)color;
    FUZZ_CHECK(b.lower.x <= b.upper.x && b.lower.y <= b.upper.y);
    fr_reenter((fr_state *)ctx, FR_CB_AABB);
}

/* The allocator: the counting one of fuzz_common.h behind the re-entry.
   The harness's own calls (quiet) neither call in nor fail. */
static void *fr_alloc_hook(size_t size, void *ctx)
{
    fr_state *s = (fr_state *)ctx;
    void *p;
    if (s->quiet) {
        long at = s->alloc.fail_at, every = s->alloc.fail_every;
        s->alloc.fail_at = s->alloc.fail_every = 0;
        p = fz_alloc_fn(size, &s->alloc);
        s->alloc.fail_at = at;
        s->alloc.fail_every = every;
        return p;
    }
    fr_reenter(s, FR_CB_ALLOC);
    return fz_alloc_fn(size, &s->alloc);
}

static void fr_free_hook(void *ptr, size_t size, void *ctx)
{
    fr_state *s = (fr_state *)ctx;
    fr_reenter(s, FR_CB_FREE); /* before the block goes: it may be the world */
    fz_free_fn(ptr, size, &s->alloc);
}

/* The twin's field: the forces the first world's field applied, in the
   same evaluations, with the same results. */
static void fr_replay_field(ga2d_world *w, void *ctx)
{
    fr_state *s = (fr_state *)ctx;
    int e = s->twin_evals++;
    FUZZ_CHECK(w == s->twin);
    while (s->replay_at < s->nlog && s->log[s->replay_at].eval == e) {
        const fr_force_call *c = &s->log[s->replay_at++];
        ga2d_result r;
        if (c->kind == 0) r = ga2d_body_apply_force(w, c->id, c->f, c->p);
        else if (c->kind == 1) r = ga2d_body_apply_force_to_center(w, c->id, c->f);
        else r = ga2d_body_apply_torque(w, c->id, c->t);
        FUZZ_CHECK(r == c->r);
    }
}

/* ------------------------------------------- one call from a callback */
static ga2d_body_def fr_body_def(fr_state *s);

/* A second world, made, stepped, drawn and destroyed from a callback:
   other worlds are unaffected by the lock. */
static void fr_other_world(fr_state *s)
{
    ga2d_world *o = ga2d_world_create(NULL);
    ga2d_body_def d = ga2d_default_body_def();
    d.polygon = ga2d_polygon_box((ga2d_real)0.5, (ga2d_real)0.5);
    ga2d_debug_draw dd = ga2d_default_debug_draw();
    ga2d_body_id id;
    FUZZ_CHECK(o != NULL);
    if (!o) return;
    d.type = GA2D_BODY_DYNAMIC;
    d.position = ga2d_vec_make(0, 1);
    id = ga2d_body_create(o, &d);
    FUZZ_CHECK(!ga2d_body_id_is_null(id));
    FUZZ_CHECK(ga2d_world_step(o, (ga2d_real)(1.0 / 60)) == GA2D_OK);
    FUZZ_CHECK(ga2d_world_draw(o, &dd) == GA2D_OK);
    FUZZ_CHECK(ga2d_body_destroy(o, id) == GA2D_OK);
    ga2d_world_destroy(o);
    (void)s;
}

/* What a force-type call must answer: LOCKED outside the force callback;
   in it, the normal rules. */
static void fr_check_force(fr_state *s, int cb, const fr_body *b, int finite_args, ga2d_result r)
{
    if (cb != FR_CB_FORCE) {
        FUZZ_CHECK(r == GA2D_ERR_LOCKED);
        return;
    }
    if (!b->valid) FUZZ_CHECK(r == GA2D_ERR_STALE_ID || (r == GA2D_ERR_NOT_FINITE && !finite_args));
    else if (!finite_args) FUZZ_CHECK(r == GA2D_ERR_NOT_FINITE);
    else if (b->type != GA2D_BODY_DYNAMIC) FUZZ_CHECK(r == GA2D_OK);
    else FUZZ_CHECK(r == GA2D_OK || r == GA2D_ERR_NOT_FINITE); /* a sum that would overflow */
    (void)s;
}

static void fr_log_force(fr_state *s, int kind, ga2d_body_id id, ga2d_vec f, ga2d_vec p, ga2d_real t, ga2d_result r)
{
    fr_force_call *c;
    if (s->nlog == FR_MAX_LOG) {
        s->log_full = 1;
        return;
    }
    c = &s->log[s->nlog++];
    memset(c, 0, sizeof *c);
    c->eval = s->cb_count[FR_CB_FORCE] - 1;
    c->kind = kind;
    c->id = id;
    c->f = f;
    c->p = p;
    c->t = t;
    c->r = r;
}

#define FR_NCALLS 64

/* One call, picked by the input from the whole API that takes a world or
   an id, on the world under way.  mut: 1 must be refused with LOCKED, 2
   LOCKED or INVALID_ARGUMENT (a NULL pointer was passed). */
static void fr_call(fr_state *s, int cb)
{
    ga2d_world *w = s->w;
    unsigned sel = fz_u8(&s->rd);
    ga2d_body_id id = fr_id(s);
    fr_body b0, b1;
    fr_view v0, v1;
    ga2d_result r = GA2D_ERR_LOCKED;
    int mut = 0, i, n;
    fr_take_body(w, id, &b0);
    fr_take_view(w, &v0);
    if (b0.valid) fr_check_live(s, &b0);
    else fr_check_dead(&b0);
    if (sel >= 250) {
        /* deferred (or, from a free hook of the world's own destruction,
           nothing); the world reads on */
        FR_TRACE((stderr, "  cb %d: destroy the world\n", cb));
        ga2d_world_destroy(w);
        if (!s->destroy_requested) s->destroy_cb = cb;
        s->destroy_requested = 1;
        sel = 0; /* then read the counters: the world is still there */
    }
    FR_TRACE((stderr, "  cb %d: call %u on %u/%u\n", cb, sel % FR_NCALLS, id.index1, id.generation));
    switch (sel % FR_NCALLS) {
    /* ---- world reads */
    case 0: {
        ga2d_world_counters c = ga2d_world_get_counters(w);
        FUZZ_CHECK(c.body_count == fr_live_count(s));
        FUZZ_CHECK(c.step_count >= 0 && c.force_evaluations >= 0 && c.speed_caps >= 0);
        break;
    }
    case 1: FUZZ_CHECK(fz_finite(ga2d_world_time(w))); break;
    case 2: FUZZ_CHECK(fz_finite_vec(ga2d_world_gravity(w))); break;
    case 3: {
        ga2d_body_id e = ga2d_world_error_body(w);
        FUZZ_CHECK(ga2d_body_id_is_null(e) || e.index1 <= 0x7FFFFFFFu);
        break;
    }
    case 4: FUZZ_CHECK(ga2d_world_snapshot_size(w) > 0); break;
    case 5: case 6: {
        int cap = fz_pick(&s->rd, 10) - 1, touching = (sel % FR_NCALLS) == 6;
        ga2d_contact_data *out = (fz_u8(&s->rd) & 7) ? s->cbuf : NULL;
        if (cap > 8) cap = 8;
        n = touching ? ga2d_world_get_contacts(w, out, cap) : ga2d_world_get_pairs(w, out, cap);
        FUZZ_CHECK(n >= 0 && n == (touching ? v0.touching : v0.pairs));
        if (out)
            for (i = 0; i < n && i < cap; ++i) fr_check_contact_data(s, &out[i], touching);
        break;
    }
    case 7: {
        ga2d_contact_events e = ga2d_world_contact_events(w);
        FUZZ_CHECK(e.begin_count >= 0 && e.end_count >= 0);
        for (i = 0; i < e.begin_count; ++i) FUZZ_CHECK(e.begin[i].manifold.count >= 1 && e.begin[i].manifold.count <= 2);
        for (i = 0; i < e.end_count; ++i) FUZZ_CHECK(e.end[i].manifold.count >= 0 && e.end[i].manifold.count <= 2);
        break;
    }
    case 8: {
        int cap = fz_pick(&s->rd, 10) - 1;
        ga2d_contact_data *out = (fz_u8(&s->rd) & 7) ? s->cbuf : NULL;
        if (cap > 8) cap = 8;
        n = ga2d_body_get_contacts(w, id, out, cap);
        FUZZ_CHECK(n >= 0 && n == b0.contacts && (n == 0 || b0.valid));
        if (out)
            for (i = 0; i < n && i < cap; ++i) {
                fr_check_contact_data(s, &out[i], 1);
                FUZZ_CHECK(ga2d_body_id_equal(out[i].body_a, id) || ga2d_body_id_equal(out[i].body_b, id));
            }
        break;
    }
    /* ---- body reads (fr_take_body made every one; these vary the argument) */
    case 9: {
        ga2d_vec p = fr_vec(s, 4, fz_u8(&s->rd) < 64);
        ga2d_vec v = ga2d_body_velocity_at(w, id, p);
        /* v + (p - c) Omega: finite when nothing in it comes near overflow */
        double reach = (fabs((double)p.x - (double)b0.center.x) + fabs((double)p.y - (double)b0.center.y)) * fabs((double)b0.w) +
                       fabs((double)b0.velocity.x) + fabs((double)b0.velocity.y);
        if (b0.valid && reach < 1e-3 * FZ_REAL_MAX) FUZZ_CHECK(fz_finite_vec(v));
        if (!b0.valid) FUZZ_CHECK(v.x == 0 && v.y == 0);
        break;
    }
    case 10: {
        const ga2d_polygon *p = ga2d_body_polygon(w, id);
        FUZZ_CHECK((p != NULL) == (b0.valid != 0));
        break;
    }
    case 11: FUZZ_CHECK(ga2d_body_is_valid(w, id) == b0.valid); break;
    case 12: {
        ga2d_body_id a = fr_id(s);
        FUZZ_CHECK(ga2d_body_id_is_null(ga2d_body_id_null()));
        FUZZ_CHECK(ga2d_body_id_equal(a, id) == (a.index1 == id.index1 && a.generation == id.generation));
        FUZZ_CHECK(ga2d_body_id_is_null(id) == (id.index1 == 0));
        break;
    }
    case 13: {
        ga2d_body_def d = fr_body_def(s);
        (void)ga2d_body_def_validate(&d);
        break;
    }
    /* ---- changes to the world: refused */
    case 14: {
        static const double dts[4] = {1.0 / 60, 0, -1, 1e-3};
        ga2d_real dt = (fz_u8(&s->rd) & 1) ? fz_narrow(dts[fz_pick(&s->rd, 4)]) : fz_real(&s->rd, 1);
        r = ga2d_world_step(w, dt);
        mut = 1;
        break;
    }
    case 15: {
        int null_draw = (fz_u8(&s->rd) & 7) == 0;
        r = ga2d_world_draw(w, null_draw ? NULL : &s->dd);
        mut = null_draw ? 2 : 1;
        break;
    }
    case 16: case 17: {
        ga2d_body_def d = fr_body_def(s);
        int null_def = (fz_u8(&s->rd) & 15) == 0;
        ga2d_body_id made = ga2d_body_create(w, null_def ? NULL : &d);
        FUZZ_CHECK(ga2d_body_id_is_null(made));
        break;
    }
    case 18: r = ga2d_body_destroy(w, id); mut = 1; break;
    case 19: r = ga2d_body_set_awake(w, id, (int)fz_u8(&s->rd) - 128); mut = 1; break;
    case 20: {
        ga2d_vec p = fr_vec(s, 4, fz_u8(&s->rd) < 128);
        ga2d_rotor q;
        q.c = fz_real(&s->rd, 1);
        q.s = fz_real(&s->rd, 1);
        r = ga2d_body_set_transform(w, id, p, q);
        mut = 1;
        break;
    }
    case 21: r = ga2d_body_set_velocity(w, id, fr_vec(s, 8, fz_u8(&s->rd) < 128)); mut = 1; break;
    case 22: r = ga2d_body_set_angular_velocity(w, id, fz_real(&s->rd, 8)); mut = 1; break;
    case 23: {
        ga2d_mass m;
        m.mass = fz_real(&s->rd, 4);
        m.center = fr_vec(s, 1, fz_u8(&s->rd) < 128);
        m.inertia = fz_real(&s->rd, 4);
        r = ga2d_body_set_mass_data(w, id, m);
        mut = 1;
        break;
    }
    case 24: r = ga2d_body_set_gravity_scale(w, id, fz_real(&s->rd, 2)); mut = 1; break;
    case 25: {
        ga2d_real lin = fz_real(&s->rd, 1);
        r = ga2d_body_set_damping(w, id, lin, fz_real(&s->rd, 1));
        mut = 1;
        break;
    }
    case 26: r = ga2d_body_set_user_data(w, id, (fz_u8(&s->rd) & 1) ? NULL : (void *)&s->tag); mut = 1; break;
    case 27: {
        ga2d_filter f;
        f.category_bits = fz_u32(&s->rd);
        f.mask_bits = fz_u32(&s->rd);
        f.group_index = (int32_t)(int8_t)fz_u8(&s->rd);
        r = ga2d_body_set_filter(w, id, f);
        mut = 1;
        break;
    }
    case 28: {
        ga2d_vec imp = fr_vec(s, 10, fz_u8(&s->rd) < 128);
        r = ga2d_body_apply_impulse(w, id, imp, fr_vec(s, 4, fz_u8(&s->rd) < 64));
        mut = 1;
        break;
    }
    case 29: r = ga2d_body_apply_angular_impulse(w, id, fz_real(&s->rd, 10)); mut = 1; break;
    case 30: r = ga2d_world_set_gravity(w, fr_vec(s, 10, fz_u8(&s->rd) < 128)); mut = 1; break;
    case 31: r = ga2d_world_set_substeps(w, (int)fz_u8(&s->rd) - 16); mut = 1; break;
    case 32: r = ga2d_world_set_integrator(w, (ga2d_integrator)fz_pick(&s->rd, GA2D_INTEGRATOR_COUNT + 1)); mut = 1; break;
    case 33:
        r = ga2d_world_set_rotation_update(w, (ga2d_rotation_update)fz_pick(&s->rd, GA2D_ROTATION_COUNT + 1));
        mut = 1;
        break;
    case 34:
        r = ga2d_world_set_force_callback(w, (fz_u8(&s->rd) & 1) ? fr_force_field : NULL, s);
        mut = 1;
        break;
    case 35: r = ga2d_world_set_solver(w, (ga2d_solver)fz_pick(&s->rd, GA2D_SOLVER_COUNT + 1)); mut = 1; break;
    case 36: r = ga2d_world_enable_sleep(w, fz_u8(&s->rd) & 1); mut = 1; break;
    case 37: r = ga2d_world_enable_warm_starting(w, fz_u8(&s->rd) & 1); mut = 1; break;
    case 38: r = ga2d_world_enable_friction(w, fz_u8(&s->rd) & 1); mut = 1; break;
    case 39: r = ga2d_world_enable_restitution(w, fz_u8(&s->rd) & 1); mut = 1; break;
    case 40: r = ga2d_world_compact(w); mut = 1; break;
    case 41: {
        /* a buffer that would hold it, or a cap too small, or NULL */
        unsigned k = fz_u8(&s->rd);
        size_t cap = k < 128 ? FR_SCRATCH : (size_t)(k & 63);
        int null_buf = (k & 7) == 0;
        r = ga2d_world_snapshot_save(w, null_buf ? NULL : s->scratch, cap);
        mut = null_buf ? 2 : 1;
        break;
    }
    case 42: {
        /* a good snapshot, a truncated one, garbage, or NULL */
        unsigned k = fz_u8(&s->rd);
        const fr_buf *b = &s->slot[k & 1];
        int null_buf = (k & 15) == 0;
        if (null_buf) {
            r = ga2d_world_snapshot_load(w, NULL, 64);
            mut = 2;
        } else if (b->n > 0 && k < 200) {
            r = ga2d_world_snapshot_load(w, b->p, k < 160 ? b->n : b->n / 2);
            mut = 1;
        } else {
            for (i = 0; i < FR_SCRATCH; ++i) s->scratch[i] = (unsigned char)fz_u8(&s->rd);
            r = ga2d_world_snapshot_load(w, s->scratch, (size_t)(k % FR_SCRATCH));
            mut = 1;
        }
        break;
    }
    /* ---- forces: the normal rules in the force callback, LOCKED elsewhere */
    case 43: case 44: case 45: {
        ga2d_vec f = fr_vec(s, 50, fz_u8(&s->rd) < 64), p = fr_vec(s, 4, fz_u8(&s->rd) < 32);
        if (fz_u8(&s->rd) & 1) p = ga2d_vec_add(b0.center, p);
        r = ga2d_body_apply_force(w, id, f, p);
        fr_check_force(s, cb, &b0, fz_finite_vec(f) && fz_finite_vec(p), r);
        if (cb == FR_CB_FORCE) fr_log_force(s, 0, id, f, p, 0, r);
        break;
    }
    case 46: case 47: {
        ga2d_vec f = fr_vec(s, 50, fz_u8(&s->rd) < 64);
        r = ga2d_body_apply_force_to_center(w, id, f);
        fr_check_force(s, cb, &b0, fz_finite_vec(f), r);
        if (cb == FR_CB_FORCE) fr_log_force(s, 1, id, f, f, 0, r);
        break;
    }
    case 48: case 49: {
        ga2d_real t = fz_u8(&s->rd) < 64 ? fz_real(&s->rd, 50) : fr_small(s, 50);
        r = ga2d_body_apply_torque(w, id, t);
        fr_check_force(s, cb, &b0, fz_finite((double)t), r);
        if (cb == FR_CB_FORCE) fr_log_force(s, 2, id, b0.center, b0.center, t, r);
        break;
    }
    /* ---- joints: made, destroyed, set from a callback: refused */
    case 53: case 54: case 55: case 56: case 57: {
        fr_jcall c;
        ga2d_joint_id made;
        int op = sel % FR_NCALLS - 53;
        fr_jcall_read(s, &c, op < 2 ? 0 : op == 2 ? 1 : 2);
        r = fr_jcall_do(w, &c, &made);
        FUZZ_CHECK(ga2d_joint_id_is_null(made));
        mut = c.op == 0 && c.null_def ? 2 : 1;
        break;
    }
    case 58: fr_check_joint(s, fr_jid(s)); break;
    case 59: {
        ga2d_vec p = fr_vec(s, 4, fz_u8(&s->rd) < 64), l = ga2d_body_local_point(w, id, p);
        if (!b0.valid) FUZZ_CHECK(l.x == 0 && l.y == 0);
        else if (fz_finite_vec(p) && fabs((double)p.x) + fabs((double)p.y) < 1e-3 * FZ_REAL_MAX) FUZZ_CHECK(fz_finite_vec(l));
        break;
    }
    /* ---- the rest */
    case 51:
        if (fz_u8(&s->rd) < 64) fr_other_world(s);
        break;
    case 52: {
        ga2d_world_def d = ga2d_default_world_def();
        FUZZ_CHECK(ga2d_world_def_validate(&d) == GA2D_OK);
        break;
    }
    default:
        /* the getters again, on the id and every tracked one */
        fr_check_world(s);
        break;
    }
    if (mut == 1) FUZZ_CHECK(r == GA2D_ERR_LOCKED);
    if (mut == 2) FUZZ_CHECK(r == GA2D_ERR_LOCKED || r == GA2D_ERR_INVALID_ARGUMENT);
    /* nothing a getter sees has changed (forces go to accumulators) */
    fr_take_body(w, id, &b1);
    fr_take_view(w, &v1);
    FUZZ_CHECK(memcmp(&b0, &b1, sizeof b0) == 0);
    FUZZ_CHECK(memcmp(&v0, &v1, sizeof v0) == 0);
}

/* ------------------------------------------------- outer calls, and twin */
static void fr_begin(fr_state *s, int op)
{
    int i;
    s->outer = op;
    s->destroy_requested = 0;
    s->destroy_cb = -1;
    memset(s->cb_count, 0, sizeof s->cb_count);
    memset(s->after_destroy, 0, sizeof s->after_destroy);
    s->count_before = ga2d_world_get_counters(s->w).body_count;
    s->failures_before = s->alloc.failures;
    s->nlog = 0;
    s->log_full = 0;
    for (i = 0; i < s->nids; ++i) s->valid_before[i] = (unsigned char)ga2d_body_is_valid(s->w, s->ids[i]);
}

static void fr_twin_drop(fr_state *s)
{
    if (s->twin) ga2d_world_destroy(s->twin);
    if (s->canon) ga2d_world_destroy(s->canon);
    s->twin = s->canon = NULL;
    s->twin_ready = 0;
    FUZZ_CHECK(s->twin_alloc.live_bytes == 0 && s->twin_alloc.live_blocks == 0);
}

/* After the outer call: 1 when the world is still there.  A world
   destroyed in the call (from a callback, or the call was the destroy) is
   freed by now, every byte of it. */
static int fr_end(fr_state *s)
{
    int gone = s->destroy_requested || s->outer == FR_OP_DESTROY;
    s->outer = FR_OP_NONE;
    if (!gone) return 1;
    FR_TRACE((stderr, "  world gone\n"));
    s->w = NULL;
    FUZZ_CHECK(s->alloc.live_bytes == 0 && s->alloc.live_blocks == 0);
    fr_twin_drop(s);
    return 0;
}

static int fr_failed(const fr_state *s) { return s->alloc.failures != s->failures_before; }

/* the world's snapshot, saved by the harness (hooks quiet) */
static int fr_save_quiet(fr_state *s, const ga2d_world *w, fr_buf *b)
{
    size_t n;
    ga2d_result r;
    int q = s->quiet;
    s->quiet = 1;
    n = ga2d_world_snapshot_size(w);
    b->n = 0;
    if (!fr_reserve(b, n)) {
        s->quiet = q;
        return 0;
    }
    r = ga2d_world_snapshot_save(w, b->p, n);
    s->quiet = q;
    FUZZ_CHECK(r == GA2D_OK);
    if (r == GA2D_OK) b->n = n;
    return r == GA2D_OK;
}

static int fr_same(const fr_buf *a, const fr_buf *b) { return a->n == b->n && (a->n == 0 || memcmp(a->p, b->p, a->n) == 0); }

/* Before an outer call that may call back: the world's snapshot, and the
   twin loaded with it when the input asked for the twin check. */
static void fr_prepare(fr_state *s)
{
    ga2d_result r;
    s->twin_ready = 0;
    s->before.n = 0;
    if (!fr_save_quiet(s, s->w, &s->before)) return;
    if (!s->twin_on || !s->twin || !s->canon) return;
    r = ga2d_world_set_force_callback(s->twin, s->field_on ? fr_replay_field : NULL, s);
    FUZZ_CHECK(r == GA2D_OK);
    r = ga2d_world_snapshot_load(s->twin, s->before.p, s->before.n);
    FUZZ_CHECK(r == GA2D_OK);
    s->twin_ready = r == GA2D_OK;
}

#ifdef FR_STRICT_SNAPSHOT
/* A snapshot in canonical form: loaded into a third world and saved again.
   A snapshot holds the body slots as the library keeps them, with fields
   that a load renumbers (tree leaves, the moving list's order, the
   union-find scratch), so a world that was loaded and one that was not
   can differ there and nowhere else. */
static void fr_canonical(fr_state *s, fr_buf *b)
{
    ga2d_result r = ga2d_world_snapshot_load(s->canon, b->p, b->n);
    FUZZ_CHECK(r == GA2D_OK);
    if (r == GA2D_OK) fr_save_quiet(s, s->canon, b);
}
#endif

/* What the getters see of a world, in a buffer: every tracked id's
   state, the counters, time, gravity, the pairs sorted by their bodies
   (each manifold with its count points: the rest means nothing), and the
   last step's error body and events (a load has none). */
static int fr_cmp_contact(const void *x, const void *y)
{
    const ga2d_contact_data *a = (const ga2d_contact_data *)x, *b = (const ga2d_contact_data *)y;
    if (a->body_a.index1 != b->body_a.index1) return a->body_a.index1 < b->body_a.index1 ? -1 : 1;
    if (a->body_b.index1 != b->body_b.index1) return a->body_b.index1 < b->body_b.index1 ? -1 : 1;
    return 0;
}

static int fr_put(fr_buf *o, const void *p, size_t n)
{
    if (!fr_reserve(o, o->n + n)) return 0;
    memcpy(o->p + o->n, p, n);
    o->n += n;
    return 1;
}

static int fr_put_contacts(fr_buf *o, const ga2d_contact_data *c, int n)
{
    static const unsigned char pad[16] = {0};
    size_t at;
    int i, k;
    if (n <= 0) return 1;
    if (o->n % 16 && !fr_put(o, pad, 16 - o->n % 16)) return 0; /* aligned for the sort */
    at = o->n;
    if (!fr_put(o, c, (size_t)n * sizeof *c)) return 0;
    {
        ga2d_contact_data *d = (ga2d_contact_data *)(void *)(o->p + at);
        for (i = 0; i < n; ++i)
            for (k = d[i].manifold.count; k < 2; ++k)
                if (k >= 0) memset(&d[i].manifold.points[k], 0, sizeof d[i].manifold.points[k]);
        qsort(d, (size_t)n, sizeof *d, fr_cmp_contact);
    }
    return 1;
}

static int fr_observe(const fr_state *s, const ga2d_world *w, int last_step, fr_buf *o)
{
    fr_view v;
    fr_body b;
    ga2d_contact_data *c;
    int i, n;
    o->n = 0;
    fr_take_view(w, &v);
    memset(&v.e, 0, sizeof v.e);
    v.snap = 0;
    if (!last_step) v.err = ga2d_body_id_null(); /* a load forgets the last step's */
    if (!fr_put(o, &v, sizeof v)) return 0;
    for (i = 0; i < s->nids; ++i) {
        fr_take_body(w, s->ids[i], &b);
        if (!fr_put(o, &b, sizeof b)) return 0;
    }
    n = ga2d_world_get_pairs(w, NULL, 0);
    c = (ga2d_contact_data *)calloc((size_t)n + 1, sizeof *c);
    if (!c) return 0;
    FUZZ_CHECK(ga2d_world_get_pairs(w, c, n) == n);
    if (!fr_put_contacts(o, c, n)) n = -1;
    if (n >= 0 && last_step) {
        ga2d_contact_events e = ga2d_world_contact_events(w);
        if (!fr_put(o, &e.begin_count, sizeof e.begin_count) || !fr_put_contacts(o, e.begin, e.begin_count) ||
            !fr_put(o, &e.end_count, sizeof e.end_count) || !fr_put_contacts(o, e.end, e.end_count))
            n = -1;
    }
    free(c);
    return n >= 0;
}

/* The world is the twin (or, refused, what it was before): the snapshot
   bytes, or else what the getters see.  (The bytes alone do not settle
   it: see fr_canonical, and a manifold's unused points, which a
   snapshot carries as the library left them.) */
static void fr_compare(fr_state *s, int with_twin, int last_step)
{
    (void)last_step;
    if (!fr_save_quiet(s, s->w, &s->after_a)) return;
    if (with_twin) {
        if (!fr_save_quiet(s, s->twin, &s->after_b)) return;
        if (fr_same(&s->after_a, &s->after_b)) return;
#ifdef FR_STRICT_SNAPSHOT
        fr_canonical(s, &s->after_a);
        fr_canonical(s, &s->after_b);
        FUZZ_CHECK(fr_same(&s->after_a, &s->after_b));
#else
        if (fr_observe(s, s->w, last_step, &s->after_a) && fr_observe(s, s->twin, last_step, &s->after_b)) {
#ifdef FUZZ_VERBOSE
            size_t i_;
            for (i_ = 0; i_ < s->after_a.n && i_ < s->after_b.n; ++i_)
                if (s->after_a.p[i_] != s->after_b.p[i_]) break;
            fprintf(stderr, "  observed: sizes %zu %zu, first difference at %zu (view %zu, body %zu x %d)\n", s->after_a.n,
                    s->after_b.n, i_, sizeof(fr_view), sizeof(fr_body), s->nids);
#endif
            FUZZ_CHECK(fr_same(&s->after_a, &s->after_b));
        }
#endif
    } else if (s->before.n > 0) {
        FUZZ_CHECK(fr_same(&s->after_a, &s->before));
    }
}

static void fr_check_ids_kept(fr_state *s)
{
    int i;
    FUZZ_CHECK(ga2d_world_get_counters(s->w).body_count == s->count_before);
    for (i = 0; i < s->nids; ++i) FUZZ_CHECK(ga2d_body_is_valid(s->w, s->ids[i]) == s->valid_before[i]);
}

/* ---------------------------------------------------------------- step */
static void fr_step(fr_state *s)
{
    static const double dts[8] = {1.0 / 60, 1.0 / 120, 1.0 / 30, 1.0 / 240, 0, -1.0 / 60, 1, 1e-30};
    unsigned k = fz_u8(&s->rd);
    ga2d_real dt = k < 200 ? fz_narrow(dts[k % 4]) : k < 250 ? fz_narrow(dts[k % 8]) : fz_real(&s->rd, 1);
    long cost = (long)s->substeps * (s->rk4 ? 4 : 1) * 12 * (ga2d_world_get_counters(s->w).body_count + 1);
    int alive, refused, twin;
    ga2d_result r, rt;
    if (s->work + cost * (s->twin_on ? 2 : 1) > FR_WORK_BUDGET) return;
    s->work += cost * (s->twin_on ? 2 : 1);
    fr_prepare(s);
    fr_begin(s, FR_OP_STEP);
    r = ga2d_world_step(s->w, dt);
    FR_TRACE((stderr, "step %g: %s (%d field calls, %d allocs)\n", (double)dt, ga2d_result_string(r),
              s->cb_count[FR_CB_FORCE], s->cb_count[FR_CB_ALLOC]));
    FUZZ_CHECK((int)r >= 0 && r < GA2D_RESULT_COUNT);
    refused = r == GA2D_ERR_INVALID_ARGUMENT || r == GA2D_ERR_TOO_LARGE;
    if (refused) FUZZ_CHECK(s->cb_count[FR_CB_FORCE] == 0 && s->cb_count[FR_CB_ALLOC] == 0 && s->cb_count[FR_CB_FREE] == 0);
    else FUZZ_CHECK(r == GA2D_OK || r == GA2D_ERR_NOT_FINITE || r == GA2D_ERR_OUT_OF_MEMORY);
    if (!refused) FUZZ_CHECK((r == GA2D_ERR_OUT_OF_MEMORY) == fr_failed(s));
    twin = s->twin_ready && !fr_failed(s) && !s->log_full && !s->destroy_requested;
    alive = fr_end(s);
    if (!alive) return;
    fr_check_ids_kept(s); /* a step neither makes nor destroys bodies */
    if (!refused) {
        ga2d_world_counters c = ga2d_world_get_counters(s->w);
        FUZZ_CHECK(c.joints_solved <= c.joint_count);
    }
    if (refused) {
        fr_compare(s, 0, 0);
        return;
    }
    if (!twin) return;
    s->twin_evals = 0;
    s->replay_at = 0;
    rt = ga2d_world_step(s->twin, dt);
    FUZZ_CHECK(rt == r);
    FUZZ_CHECK(s->twin_evals == s->cb_count[FR_CB_FORCE]);
    FUZZ_CHECK(s->replay_at == s->nlog);
    FUZZ_CHECK(ga2d_body_id_equal(ga2d_world_error_body(s->w), ga2d_world_error_body(s->twin)));
    {
        ga2d_contact_events a = ga2d_world_contact_events(s->w), b = ga2d_world_contact_events(s->twin);
        FUZZ_CHECK(a.begin_count == b.begin_count && a.end_count == b.end_count);
    }
    fr_compare(s, 1, 1);
}

/* ---------------------------------------------------------------- draw */
static void fr_draw(fr_state *s)
{
    ga2d_result r;
    int points = 0, n, i;
    fr_prepare(s);
    fr_begin(s, FR_OP_DRAW);
    r = ga2d_world_draw(s->w, &s->dd);
    FR_TRACE((stderr, "draw: %s\n", ga2d_result_string(r)));
    FUZZ_CHECK(r == GA2D_OK);
    if (!s->destroy_requested) {
        /* what was drawn: each body once, each touching contact's points */
        n = ga2d_world_get_contacts(s->w, NULL, 0);
        for (i = 0; i < n; ++i) {
            fr_buf *b = &s->tmp;
            ga2d_contact_data *c;
            if (i == 0) {
                if (!fr_reserve(b, (size_t)n * sizeof *c)) break;
                FUZZ_CHECK(ga2d_world_get_contacts(s->w, (ga2d_contact_data *)(void *)b->p, n) == n);
            }
            c = (ga2d_contact_data *)(void *)b->p;
            points += c[i].manifold.count;
        }
        FUZZ_CHECK(s->cb_count[FR_CB_POLYGON] == s->count_before);
        FUZZ_CHECK(s->cb_count[FR_CB_AABB] == s->count_before);
        FUZZ_CHECK(s->cb_count[FR_CB_POINT] == s->count_before);
        FUZZ_CHECK(s->cb_count[FR_CB_CONTACT] == points);
        /* each joint: three segments (A's centre, the anchors, B's centre) */
        FUZZ_CHECK(s->cb_count[FR_CB_SEGMENT] == 3 * ga2d_world_get_counters(s->w).joint_count);
    }
    if (!fr_end(s)) return;
    fr_check_ids_kept(s);
    fr_compare(s, 0, 0); /* read-only: the same bits */
}

/* --------------------------------------------------------------- bodies */
static ga2d_body_def fr_body_def(fr_state *s)
{
    ga2d_body_def d = ga2d_default_body_def();
    unsigned flags = fz_u8(&s->rd), t = fz_u8(&s->rd) % 8;
    d.type = t == 0 ? GA2D_BODY_STATIC : t == 1 ? GA2D_BODY_KINEMATIC : GA2D_BODY_DYNAMIC;
    /* one read a statement: a function's arguments are evaluated in no set
       order (gcc and clang differ), and an input must mean one scene */
    if (fz_u8(&s->rd) & 1) {
        ga2d_real hw = fz_narrow(0.1 + fz_u8(&s->rd) / 128.0);
        d.polygon = ga2d_polygon_box(hw, fz_narrow(0.1 + fz_u8(&s->rd) / 128.0));
    } else {
        int count = 3 + fz_pick(&s->rd, GA2D_MAX_POLYGON_VERTICES - 2);
        d.polygon = ga2d_polygon_regular(count, fz_narrow(0.1 + fz_u8(&s->rd) / 128.0));
    }
    d.position.x = fr_small(s, 1);
    d.position.y = fz_narrow(fz_u8(&s->rd) / 32.0);
    if (flags & 1) d.rotor = ga2d_rotor_from_angle(fr_small(s, 0.5));
    if (flags & 2) {
        d.velocity = fr_vec(s, 4, 0);
        d.angular_velocity = fr_small(s, 4);
    }
    if (flags & 4) {
        /* anything: the def may be refused */
        d.density = fz_real(&s->rd, 4);
        d.friction = fz_real_pos(&s->rd, 1);
        d.restitution = fz_real_pos(&s->rd, 1);
        d.linear_damping = fz_real_pos(&s->rd, 1);
        d.gravity_scale = fz_real(&s->rd, 2);
        d.position = fr_vec(s, 4, 1);
    }
    if (flags & 8) {
        d.filter.category_bits = (uint32_t)1 << (fz_u8(&s->rd) & 31);
        d.filter.mask_bits = fz_u32(&s->rd);
        d.filter.group_index = (int32_t)(int8_t)fz_u8(&s->rd);
    }
    if (flags & 16) d.is_awake = 0;
    if (flags & 32) d.fixed_rotation = 1;
    d.user_data = &s->tag;
    return d;
}

static void fr_create(fr_state *s, const ga2d_body_def *d)
{
    ga2d_result valid = ga2d_body_def_validate(d);
    ga2d_body_id id, tid;
    int twin;
    if (s->nids == FR_MAX_IDS) return;
    fr_prepare(s);
    fr_begin(s, FR_OP_CREATE);
    id = ga2d_body_create(s->w, d);
    FR_TRACE((stderr, "create type %d: %s -> %u/%u (%d allocs) p (%g %g) density %g friction %g restitution %g\n", (int)d->type,
              ga2d_result_string(valid), id.index1, id.generation, s->cb_count[FR_CB_ALLOC], (double)d->position.x,
              (double)d->position.y, (double)d->density, (double)d->friction, (double)d->restitution));
#ifdef FUZZ_VERBOSE
    {
        int j_;
        for (j_ = 0; j_ < d->polygon.count && j_ < GA2D_MAX_POLYGON_VERTICES; ++j_)
            fprintf(stderr, "   v%d (%.9g, %.9g)\n", j_, (double)d->polygon.vertices[j_].x, (double)d->polygon.vertices[j_].y);
        fprintf(stderr, "   rotor (%.9g %.9g) v (%g %g) w %g damping %g gs %g fixed %d awake %d filter %x %x %d\n", (double)d->rotor.c,
                (double)d->rotor.s, (double)d->velocity.x, (double)d->velocity.y, (double)d->angular_velocity,
                (double)d->linear_damping, (double)d->gravity_scale, d->fixed_rotation, d->is_awake, d->filter.category_bits,
                d->filter.mask_bits, d->filter.group_index);
    }
#endif
    twin = s->twin_ready && !fr_failed(s);
    if (valid != GA2D_OK) FUZZ_CHECK(ga2d_body_id_is_null(id) && s->cb_count[FR_CB_ALLOC] == 0);
    if (fr_failed(s)) FUZZ_CHECK(ga2d_body_id_is_null(id));
    if (!fr_end(s)) return;
    if (ga2d_body_id_is_null(id)) {
        FUZZ_CHECK(valid != GA2D_OK || fr_failed(s));
        fr_check_ids_kept(s);
        fr_compare(s, 0, 0); /* refused: as it was */
        return;
    }
    FUZZ_CHECK(ga2d_body_is_valid(s->w, id));
    FUZZ_CHECK(ga2d_world_get_counters(s->w).body_count == s->count_before + 1);
    s->ids[s->nids++] = id;
    if (!twin) return;
    tid = ga2d_body_create(s->twin, d);
    FUZZ_CHECK(ga2d_body_id_equal(id, tid));
    fr_compare(s, 1, 0);
}

/* An outer body call: a setter, a force, an impulse, a destroy. */
static void fr_body_op(fr_state *s)
{
    ga2d_body_id id = fr_id(s);
    unsigned k = fz_u8(&s->rd);
    int wild = k >= 224, valid = ga2d_body_is_valid(s->w, id), op = (int)(k % 15);
    ga2d_result r;
    fr_begin(s, FR_OP_BODY);
    switch (op) {
    case 0: { /* one read a statement: see fr_body_def */
        ga2d_vec p = fr_vec(s, 2, wild);
        r = ga2d_body_set_transform(s->w, id, p, ga2d_rotor_from_angle(fr_small(s, 1)));
        break;
    }
    case 1: r = ga2d_body_set_velocity(s->w, id, fr_vec(s, 4, wild)); break;
    case 2: r = ga2d_body_set_angular_velocity(s->w, id, wild ? fz_real(&s->rd, 4) : fr_small(s, 4)); break;
    case 3: {
        ga2d_mass m;
        m.mass = fz_narrow(0.1 + fz_u8(&s->rd) / 16.0);
        m.center = fr_vec(s, 0.25, 0);
        m.inertia = fz_narrow((fz_u8(&s->rd) & 3) ? 0.01 + fz_u8(&s->rd) / 32.0 : 0);
        r = ga2d_body_set_mass_data(s->w, id, m);
        break;
    }
    case 4: r = ga2d_body_set_gravity_scale(s->w, id, wild ? fz_real(&s->rd, 1) : fr_small(s, 2)); break;
    case 5: {
        ga2d_real lin = fz_narrow(fz_u8(&s->rd) / 64.0);
        r = ga2d_body_set_damping(s->w, id, lin, fz_narrow(fz_u8(&s->rd) / 64.0));
        break;
    }
    case 6: r = ga2d_body_set_user_data(s->w, id, (fz_u8(&s->rd) & 1) ? NULL : (void *)&s->tag); break;
    case 7: {
        ga2d_filter f = ga2d_default_filter();
        if (wild) f.mask_bits = fz_u32(&s->rd);
        r = ga2d_body_set_filter(s->w, id, f);
        break;
    }
    case 8: r = ga2d_body_set_awake(s->w, id, fz_u8(&s->rd) & 1); break;
    case 9: r = ga2d_body_apply_force(s->w, id, fr_vec(s, 20, wild), ga2d_body_center(s->w, id)); break;
    case 10: r = ga2d_body_apply_force_to_center(s->w, id, fr_vec(s, 20, wild)); break;
    case 11: r = ga2d_body_apply_torque(s->w, id, wild ? fz_real(&s->rd, 20) : fr_small(s, 20)); break;
    case 12: r = ga2d_body_apply_impulse(s->w, id, fr_vec(s, 4, wild), ga2d_body_center(s->w, id)); break;
    case 13: r = ga2d_body_apply_angular_impulse(s->w, id, wild ? fz_real(&s->rd, 4) : fr_small(s, 4)); break;
    default: r = ga2d_body_destroy(s->w, id); break;
    }
    FR_TRACE((stderr, "body op %d on %u/%u: %s\n", op, id.index1, id.generation, ga2d_result_string(r)));
    FUZZ_CHECK((int)r >= 0 && r < GA2D_RESULT_COUNT);
    if (!valid) FUZZ_CHECK(r == GA2D_ERR_STALE_ID);
    if (!fr_end(s)) return;
    FUZZ_CHECK(ga2d_world_get_counters(s->w).body_count == s->count_before - (op == 14 && r == GA2D_OK));
}

/* An outer joint call: allocations call in (a maker grows the pool).  A
   refused call leaves the world's bytes as they were; with the twin, the
   same call there gives the same answer and the same world. */
static void fr_joint(fr_state *s)
{
    fr_jcall c;
    ga2d_joint_id made, tmade;
    ga2d_result r, rt;
    int twin, joints;
    fr_jcall_read(s, &c, fz_pick(&s->rd, 4) == 0 ? 1 : fz_pick(&s->rd, 2) ? 0 : 2);
    joints = ga2d_world_get_counters(s->w).joint_count;
    fr_prepare(s);
    fr_begin(s, FR_OP_JOINT);
    r = fr_jcall_do(s->w, &c, &made);
    FR_TRACE((stderr, "joint op %d kind %d which %d on %u/%u (bodies %u %u): %s -> %u (%d allocs)\n", c.op, c.kind, c.which,
              c.id.index1, c.id.generation, c.a.index1, c.b.index1, ga2d_result_string(r), made.index1, s->cb_count[FR_CB_ALLOC]));
    FUZZ_CHECK((int)r >= 0 && r < GA2D_RESULT_COUNT && r != GA2D_ERR_LOCKED);
    if (c.op == 0) FUZZ_CHECK((r == GA2D_OK) == !ga2d_joint_id_is_null(made));
    if (c.null_def && c.op == 0) FUZZ_CHECK(r == GA2D_ERR_INVALID_ARGUMENT);
    if (r == GA2D_ERR_OUT_OF_MEMORY) FUZZ_CHECK(fr_failed(s));
    twin = s->twin_ready && !fr_failed(s) && !s->destroy_requested;
    if (!fr_end(s)) return;
    fr_check_ids_kept(s); /* a joint call makes and destroys no body */
    if (r != GA2D_OK) {
        FUZZ_CHECK(ga2d_world_get_counters(s->w).joint_count == joints);
        fr_compare(s, 0, 0); /* refused: as it was */
        return;
    }
    FUZZ_CHECK(ga2d_world_get_counters(s->w).joint_count == joints + (c.op == 0) - (c.op == 1));
    if (c.op == 0) {
        static const int type_of[4] = {GA2D_JOINT_REVOLUTE, GA2D_JOINT_DISTANCE, GA2D_JOINT_WELD, GA2D_JOINT_MOTOR};
        FUZZ_CHECK(ga2d_joint_is_valid(s->w, made) && (int)ga2d_joint_get_type(s->w, made) == type_of[c.kind]);
        fr_remember_joint(s, made);
    }
    fr_check_joint(s, c.op == 0 ? made : c.id);
    if (!twin) return;
    rt = fr_jcall_do(s->twin, &c, &tmade);
    FUZZ_CHECK(rt == r && ga2d_joint_id_equal(made, tmade));
    fr_compare(s, 1, 0);
}

/* ------------------------------------------------------------ snapshots */
static void fr_save(fr_state *s)
{
    unsigned k = fz_u8(&s->rd);
    fr_buf *b = &s->slot[k & 1];
    size_t n = ga2d_world_snapshot_size(s->w), cap = (k & 6) == 6 ? n - 1 : n;
    ga2d_result r;
    int twin;
    if (!fr_reserve(b, n)) return;
    b->n = 0;
    fr_prepare(s);
    fr_begin(s, FR_OP_SAVE);
    r = ga2d_world_snapshot_save(s->w, b->p, cap);
    FR_TRACE((stderr, "save %zu: %s\n", cap, ga2d_result_string(r)));
    if (cap < n) FUZZ_CHECK(r == GA2D_ERR_BUFFER_TOO_SMALL && s->cb_count[FR_CB_ALLOC] == 0);
    else FUZZ_CHECK(r == GA2D_OK || r == GA2D_ERR_OUT_OF_MEMORY);
    if (cap == n) FUZZ_CHECK((r == GA2D_ERR_OUT_OF_MEMORY) == fr_failed(s));
    if (r == GA2D_OK) b->n = n; /* kept even if the world went: it saved itself first */
    twin = s->twin_ready && !fr_failed(s);
    if (!fr_end(s)) return;
    fr_check_ids_kept(s);
    fr_compare(s, 0, 0); /* save changes nothing */
    if (twin && r == GA2D_OK && fr_save_quiet(s, s->twin, &s->after_b) && !fr_same(b, &s->after_b)) {
        /* the same world: its save loads into what the twin's does */
#ifdef FR_STRICT_SNAPSHOT
        if (!fr_reserve(&s->after_a, b->n)) return;
        memcpy(s->after_a.p, b->p, b->n);
        s->after_a.n = b->n;
        fr_canonical(s, &s->after_a);
        fr_canonical(s, &s->after_b);
        FUZZ_CHECK(fr_same(&s->after_a, &s->after_b));
#else
        FUZZ_CHECK(ga2d_world_snapshot_load(s->canon, b->p, b->n) == GA2D_OK);
        if (!fr_observe(s, s->canon, 0, &s->after_a)) return;
        FUZZ_CHECK(ga2d_world_snapshot_load(s->canon, s->after_b.p, s->after_b.n) == GA2D_OK);
        if (fr_observe(s, s->canon, 0, &s->after_b)) FUZZ_CHECK(fr_same(&s->after_a, &s->after_b));
#endif
    }
}

static void fr_load(fr_state *s)
{
    unsigned k = fz_u8(&s->rd);
    fr_buf *b = &s->slot[k & 1];
    size_t n = b->n;
    ga2d_result r, rt;
    int twin;
    if (n == 0) return;
    if ((k & 6) == 6) {
        /* a corrupted copy: refused, and nothing changes */
        if (!fr_reserve(&s->tmp, n)) return;
        memcpy(s->tmp.p, b->p, n);
        {
            size_t at = fz_u16(&s->rd) % n; /* before the flip's byte: one order */
            s->tmp.p[at] ^= (unsigned char)(1 + fz_u8(&s->rd) % 255);
        }
        b = &s->tmp;
    }
    fr_prepare(s);
    fr_begin(s, FR_OP_LOAD);
    r = ga2d_world_snapshot_load(s->w, b->p, n);
    FR_TRACE((stderr, "load %zu: %s\n", n, ga2d_result_string(r)));
    FUZZ_CHECK(r == GA2D_OK || r == GA2D_ERR_BAD_SNAPSHOT || r == GA2D_ERR_OUT_OF_MEMORY);
    FUZZ_CHECK((r == GA2D_ERR_OUT_OF_MEMORY) == (fr_failed(s) && r != GA2D_OK));
    twin = s->twin_ready && !fr_failed(s);
    if (!fr_end(s)) return;
    if (r != GA2D_OK) {
        fr_check_ids_kept(s);
        fr_compare(s, 0, 0); /* on any error the world is as it was */
        return;
    }
    /* the loaded world may have another def: budget for the worst */
    s->substeps = 8;
    s->rk4 = 1;
    FUZZ_CHECK(ga2d_world_get_counters(s->w).body_count == fr_live_count(s));
    if (!twin) return;
    rt = ga2d_world_snapshot_load(s->twin, b->p, n);
    FUZZ_CHECK(rt == r);
    fr_compare(s, 1, 0);
}

/* --------------------------------------------------------------- world */
static void fr_world_op(fr_state *s)
{
    unsigned k = fz_u8(&s->rd), op = k % 9;
    ga2d_result r = GA2D_OK;
    int twin = 0;
    if (op == 2 || op == 7) fr_prepare(s); /* they may allocate */
    fr_begin(s, FR_OP_WORLD);
    switch (op) {
    case 0: {
        ga2d_vec g = fr_vec(s, 10, k >= 240);
        r = ga2d_world_set_gravity(s->w, g);
        FUZZ_CHECK(r == GA2D_OK || r == GA2D_ERR_NOT_FINITE || r == GA2D_ERR_TOO_LARGE);
        break;
    }
    case 1: {
        int n = (k >> 4) ? 1 + (int)(k >> 4) % 8 : (int)fz_u8(&s->rd) - 16;
        r = ga2d_world_set_substeps(s->w, n);
        FUZZ_CHECK(r == ((n >= 1 && n <= 1024) ? GA2D_OK : GA2D_ERR_INVALID_ARGUMENT));
        if (r == GA2D_OK && n > s->substeps) s->substeps = n;
        break;
    }
    case 2: {
        int m = fz_pick(&s->rd, GA2D_INTEGRATOR_COUNT);
        r = ga2d_world_set_integrator(s->w, (ga2d_integrator)m);
        FUZZ_CHECK(r == GA2D_OK || r == GA2D_ERR_OUT_OF_MEMORY);
        FUZZ_CHECK((r == GA2D_ERR_OUT_OF_MEMORY) == fr_failed(s));
        if (r == GA2D_OK && m == GA2D_INTEGRATOR_RK4) s->rk4 = 1;
        twin = s->twin_ready && !fr_failed(s) && !s->destroy_requested;
        if (twin) FUZZ_CHECK(ga2d_world_set_integrator(s->twin, (ga2d_integrator)m) == r);
        break;
    }
    case 3: r = ga2d_world_set_rotation_update(s->w, (ga2d_rotation_update)fz_pick(&s->rd, GA2D_ROTATION_COUNT)); break;
    case 4: r = ga2d_world_set_solver(s->w, (ga2d_solver)fz_pick(&s->rd, GA2D_SOLVER_COUNT)); break;
    case 5:
        switch (fz_pick(&s->rd, 4)) {
        case 0: r = ga2d_world_enable_sleep(s->w, (k >> 4) & 1); break;
        case 1: r = ga2d_world_enable_warm_starting(s->w, (k >> 4) & 1); break;
        case 2: r = ga2d_world_enable_friction(s->w, (k >> 4) & 1); break;
        default: r = ga2d_world_enable_restitution(s->w, (k >> 4) & 1); break;
        }
        break;
    case 6:
        s->field_on = (k >> 4) & 1;
        r = ga2d_world_set_force_callback(s->w, s->field_on ? fr_force_field : NULL, s);
        break;
    case 7:
        r = ga2d_world_compact(s->w);
        FUZZ_CHECK(r == GA2D_OK || r == GA2D_ERR_OUT_OF_MEMORY);
        FUZZ_CHECK((r == GA2D_ERR_OUT_OF_MEMORY) == fr_failed(s));
        twin = s->twin_ready && !fr_failed(s) && !s->destroy_requested;
        if (twin) FUZZ_CHECK(ga2d_world_compact(s->twin) == GA2D_OK);
        break;
    default: break;
    }
    FR_TRACE((stderr, "world op %u: %s\n", op, ga2d_result_string(r)));
    FUZZ_CHECK((int)r >= 0 && r < GA2D_RESULT_COUNT);
    if (!fr_end(s)) return;
    fr_check_ids_kept(s);
    /* refused for memory: as it was; else as the twin */
    if ((op == 2 || op == 7) && (r != GA2D_OK || twin)) fr_compare(s, r == GA2D_OK, 0);
}

/* Builds a world from the input: its def within the valid ranges, ground,
   a few bodies on it.  0 when none could be made. */
static int fr_build(fr_state *s)
{
    static const double units[5] = {0, 1, 0.5, 2, 8};
    ga2d_world_def d = ga2d_default_world_def();
    unsigned flags = fz_u8(&s->rd), k;
    int i, n;
    ga2d_world *w;
    FUZZ_CHECK(s->alloc.live_bytes == 0 && s->alloc.live_blocks == 0);
    memset(&s->alloc, 0, sizeof s->alloc);
    d.length_units_per_meter = fz_narrow(units[fz_pick(&s->rd, 5)]);
    d.gravity.x = fz_narrow(((int)(fz_u8(&s->rd) % 21) - 10) * 0.5);
    d.gravity.y = fz_narrow(-(double)(fz_u8(&s->rd) % 11));
    d.substeps = 1 + fz_pick(&s->rd, 8);
    d.integrator = (ga2d_integrator)fz_pick(&s->rd, GA2D_INTEGRATOR_COUNT);
    d.rotation_update = (ga2d_rotation_update)fz_pick(&s->rd, GA2D_ROTATION_COUNT);
    d.solver = (ga2d_solver)fz_pick(&s->rd, GA2D_SOLVER_COUNT);
    if (flags & 1) {
        d.velocity_iterations = fz_pick(&s->rd, 9);
        d.position_iterations = fz_pick(&s->rd, 5);
        d.contact_hertz = fz_narrow(fz_pick(&s->rd, 61));
        d.contact_damping_ratio = fz_narrow(fz_u8(&s->rd) / 16.0);
        d.contact_push_max_velocity = fz_narrow(fz_u8(&s->rd) / 64.0);
        d.restitution_threshold = fz_narrow(fz_u8(&s->rd) / 64.0);
    }
    k = fz_u8(&s->rd);
    d.enable_sleep = (int)(k & 1);
    d.enable_warm_starting = (int)((k >> 1) & 1);
    d.enable_friction = (int)((k >> 2) & 1);
    d.enable_restitution = (int)((k >> 3) & 1);
    if (flags & 2) {
        /* an allocator that fails: attempt k, and maybe every j-th after */
        s->alloc.fail_at = 1 + fz_u8(&s->rd);
        s->alloc.fail_every = fz_u8(&s->rd) < 160 ? 0 : 4 + fz_u8(&s->rd) % 32;
    }
    d.allocator.alloc = fr_alloc_hook;
    d.allocator.free = fr_free_hook;
    d.allocator.ctx = s;
    s->field_on = (flags & 4) != 0;
    if (s->field_on) {
        d.force_callback = fr_force_field;
        d.force_context = s;
    }
    FUZZ_CHECK(ga2d_world_def_validate(&d) == GA2D_OK);
    s->w = NULL; /* hooks do not call in while it is being made */
    w = ga2d_world_create(&d);
    FR_TRACE((stderr, "world %d: flags %u substeps %d integrator %d solver %d fail_at %ld/%ld g (%g %g) units %g switches %d%d%d%d -> %p\n",
              s->worlds, flags, d.substeps, (int)d.integrator, (int)d.solver, s->alloc.fail_at, s->alloc.fail_every,
              (double)d.gravity.x, (double)d.gravity.y, (double)d.length_units_per_meter, d.enable_sleep, d.enable_warm_starting,
              d.enable_friction, d.enable_restitution, (void *)w));
    ++s->worlds;
    if (!w) {
        FUZZ_CHECK(s->alloc.failures > 0 && s->alloc.live_bytes == 0);
        return 0;
    }
    s->w = w;
    s->substeps = d.substeps;
    s->rk4 = d.integrator == GA2D_INTEGRATOR_RK4;
    /* the twin: the same def, a plain allocator, the field replayed */
    s->twin_on = (flags & 8) != 0;
    if (s->twin_on) {
        ga2d_world_def td = d;
        memset(&s->twin_alloc, 0, sizeof s->twin_alloc);
        fz_alloc_attach(&s->twin_alloc, &td);
        td.force_callback = NULL;
        td.force_context = NULL;
        s->twin = ga2d_world_create(&td);
        s->canon = ga2d_world_create(&td);
        FUZZ_CHECK(s->twin != NULL && s->canon != NULL);
    }
    /* ground, and a few bodies on it */
    n = fz_pick(&s->rd, 3);
    for (i = 0; i < n && s->w; ++i) {
        ga2d_body_def b = ga2d_default_body_def();
        b.polygon = ga2d_polygon_box(4, (ga2d_real)0.25);
        b.position = ga2d_vec_make((ga2d_real)(i * 3 - 3), (ga2d_real)(-0.25 - i));
        b.user_data = &s->tag;
        fr_create(s, &b);
    }
    n = fz_pick(&s->rd, 9);
    for (i = 0; i < n && s->w; ++i) {
        ga2d_body_def b = ga2d_default_body_def();
        b.type = GA2D_BODY_DYNAMIC;
        if (fz_u8(&s->rd) & 1) b.polygon = ga2d_polygon_box((ga2d_real)0.25, (ga2d_real)0.25);
        else b.polygon = ga2d_polygon_regular(3 + fz_pick(&s->rd, GA2D_MAX_POLYGON_VERTICES - 2), (ga2d_real)0.3);
        b.position = ga2d_vec_make((ga2d_real)((i % 3 - 1) * 0.55), (ga2d_real)(0.26 + (i / 3) * 0.52));
        b.user_data = &s->tag;
        fr_create(s, &b);
    }
    return s->w != NULL;
}

static int fuzz_reentry_one(const uint8_t *data, size_t size)
{
    fr_state *s = (fr_state *)calloc(1, sizeof(fr_state));
    int ops = 0, i;
    if (!s) return 0;
    fz_init(&s->rd, data, size);
    s->dd = ga2d_default_debug_draw();
    s->dd.polygon = fr_draw_polygon;
    s->dd.segment = fr_draw_segment;
    s->dd.point = fr_draw_point;
    s->dd.contact = fr_draw_contact;
    s->dd.aabb = fr_draw_aabb;
    s->dd.draw_bodies = s->dd.draw_contacts = s->dd.draw_aabbs = s->dd.draw_centers = 1;
    s->dd.context = s;
    while (s->worlds < FR_MAX_WORLDS && (s->worlds == 0 || fz_more(&s->rd))) {
        if (!fr_build(s)) continue;
        while (s->w && fz_more(&s->rd) && ops++ < FR_MAX_OPS) {
            int op = fz_pick(&s->rd, 32);
            if (op < 9) fr_step(s);
            else if (op < 13) fr_draw(s);
            else if (op < 16) {
                ga2d_body_def d = fr_body_def(s);
                fr_create(s, &d);
            } else if (op < 21) fr_body_op(s);
            else if (op < 23) fr_save(s);
            else if (op < 25) fr_load(s);
            else if (op < 29) fr_world_op(s);
            else if (op < 30) {
                fr_begin(s, FR_OP_DESTROY);
                ga2d_world_destroy(s->w);
                fr_end(s);
            } else if (op == 31) fr_joint(s);
            else fr_check_world(s);
        }
        if (s->w) {
            /* the end: the world's own destruction, its free hooks calling in */
            fr_begin(s, FR_OP_DESTROY);
            ga2d_world_destroy(s->w);
            fr_end(s);
        }
    }
    fr_twin_drop(s);
    for (i = 0; i < 2; ++i) free(s->slot[i].p);
    free(s->before.p);
    free(s->after_a.p);
    free(s->after_b.p);
    free(s->tmp.p);
    free(s);
    return 0;
}

#endif
