/* World fuzzing with shapes: the world harness's world, bodies, steps and
   setters (fuzz_world.h, reused as is), plus what shapes brought: bodies
   made bare or with a polygon, then shapes of every type created on them
   (through each typed maker and ga2d_shape_create_checked; on live,
   destroyed, null and forged body ids; clean geometry and wild: NaN,
   huge, negative radii, coincident ends, inconsistent polygons, a lone
   chain segment, a type out of range), destroyed (with or without a mass
   update; chain segments, stale ids), their materials and filters set;
   sensors (sensor events on and off); chains, open and loops, on static,
   kinematic, dynamic and stale bodies (random paths, valley rows with
   concave and convex joins by turns, stars with concave corners either
   way round, and points out to +-GA2D_MAX_COORDINATE), with repeated,
   nearly repeated, collinear, folded, huge and NaN points, and destroyed;
   heavy shapes (a density a power of two below the largest real, placed
   out to the coordinate bound) summed on one body; pre-solve and hit
   events switched on per shape, with a world pre-solve callback that
   accepts, refuses or picks by ids, and may write garbage through the
   manifold it is handed; conveyor speeds; checkpoints saved,
   loaded into another world and back into this one (rollback), and
   replays: the same steps from one snapshot in two worlds; joints of
   every kind (revolute, distance, weld, motor) made on live, stale, null,
   forged, static and same bodies, through the checked and the plain
   makers and with a NULL def or out, their numbers ordinary or hostile
   (NaN, inf, huge, negative, a limit's lower above its upper, length 0,
   anchors and offsets past the coordinate bound, a hand-zeroed def),
   collide_connected either way; destroyed (live, stale, forged ids, and
   with their bodies); every setter, of the joint's kind or another, with
   good and bad values; the getters.

   What is checked (the header's promises, besides fuzz_world.h's):
     - every call answers with a result in range (no crash, no sanitizer
       report, no leak: the counting allocator gets every byte back);
     - a refused shape, chain or setter call leaves the world unchanged:
       its snapshot is the same bytes before and after; a shape or chain
       made by a clean def on a live body is made unless an allocation
       failed (then OUT_OF_MEMORY); a stale body is STALE_ID, a chain
       segment given to ga2d_shape_destroy INVALID_ARGUMENT, a segment or
       chain on a dynamic body INVALID_ARGUMENT; a made shape reads back
       (body, type, geometry, filter, user data, last in the body's list)
       and a sensor or zero-density shape changes no mass; a made chain has
       one segment per edge, through the given points, its ghosts the
       neighbours (an open end's behind the end at a right angle); a
       destroyed shape or chain is stale, and so are the shapes of a
       destroyed body;
     - mass sums: MASS_OVERFLOW only where a body's sums can pass the
       range (heavy shapes were made, or the body spins past MAX / 8 M),
       and then nothing changed; a dynamic body's mass data stay finite
       after every creation and destruction;
     - whatever a world accepted, its snapshot loads: a round trip after
       chains and heavy shapes, besides the usual ones;
     - a sleeping tracked body that the force field pushes (its torque
       field_k finite and not zero) is awake after the step;
     - sensors: every begin is matched by one end (also when either shape
       or its body goes: the end comes with the next step), the pairs open
       after a step are exactly each sensor's overlaps, and every overlap
       is of a live non-sensor shape on another body that takes sensor
       events;
     - hits: finite, faster than the threshold, on contacts one of whose
       shapes asked for them, never on a contact the pre-solve refused;
     - the pre-solve callback: only from a step, for touching contacts of
       two live shapes on two bodies one of which asked for it; inside it
       every change (stepping, creating and destroying bodies, shapes and
       chains, setters, forces, impulses, snapshots, compaction, drawing)
       is refused with LOCKED and changes nothing; garbage it writes
       through the manifold changes nothing (a replay whose twin writes
       none ends in the same bytes);
     - snapshots: a saved world loads into another (same def) and saves to
       the same bytes; loaded back into this one it saves the same bytes;
       two worlds loaded from one snapshot and stepped alike end in the
       same bytes (the callbacks decide from ids alone);
     - joints: a maker answers one of the errors its def has (STALE_ID,
       INVALID_ARGUMENT, NOT_FINITE, TOO_LARGE), OK when it has none and no
       allocation failed, OUT_OF_MEMORY only when one did; a setter
       STALE_ID for a stale id, INVALID_ARGUMENT for another kind, else its
       value's errors; a refused call changes no byte of the world; a made
       joint reads back (kind, bodies, user data, collide_connected) and
       the count goes up by one, a destroyed one reads zero everywhere and
       the count down; a made, set or destroyed joint's dynamic bodies are
       awake; a joint lives exactly while both its bodies do (destroying a
       body makes its joints stale); joined dynamic bodies sleep and wake
       together (one island); bodies joined with collide_connected 0 have
       no pair; readings (reaction force and torque, angle, speed, length)
       are finite, the angle within (-pi, pi]; joint_count counts the live
       joints, and after a step joints_solved <= joint_count; the
       pre-solve callback's and the force field's joint calls are LOCKED
       and change nothing; whatever a world with joints accepted, its
       snapshot loads and saves to the same bytes.

   Findings this harness made, each fixed in the header and its input kept
   in tests/fuzz/regress/shape_world/: a body destroyed with its chains
   freed through the allocator hook outside the world's bracket; a lone
   chain segment made by ga2d_shape_create_checked (now INVALID_ARGUMENT),
   whose world no snapshot could load; a contained body keeping the
   field's non-finite cache, which the loader refuses; a sensor end event
   that found no room counted as pending (the next step now reports
   OUT_OF_MEMORY); a revolute joint's reference angle of 1e30 that hung
   the angle's wrap (now cut by the exact remainder first); a joint's user
   data that a snapshot did not carry (read back NULL after a rollback). */
#ifndef GA2D_FUZZ_SHAPE_WORLD_H
#define GA2D_FUZZ_SHAPE_WORLD_H

#include "fuzz_world.h"

#define FSW_MAX_SHAPES 96
#define FSW_MAX_CHAINS 8
#define FSW_MAX_POINTS 12
#define FSW_MAX_OPEN 1024
#define FSW_MAX_OPS 160
#define FSW_SCRATCH 256
#define FSW_MAX_JOINTS 48
/* op 39 followed by a byte at least this is a query op (fsw_query_op) */
#define FSW_QUERY_MARK 0xC0

#ifdef FUZZ_VERBOSE
#define FSW_TRACE(args) (fprintf args)
#else
#define FSW_TRACE(args) ((void)0)
#endif

/* A shape the harness made (or tried to): its id and what it asked for.
   Shapes the harness did not make (a body def's polygon, chain segments)
   asked for nothing. */
typedef struct fsw_shape {
    ga2d_shape_id id;
    ga2d_body_id body;
    int type, sensor, sensor_events, pre_solve, hit;
} fsw_shape;

typedef struct fsw_chain {
    ga2d_chain_id id;
    ga2d_body_id body;
    int n;
    ga2d_shape_id segments[FSW_MAX_POINTS];
} fsw_chain;

/* A joint the harness made: its id, what it was made with, and a
   revolute joint's limits while the harness knows them. */
typedef struct fsw_joint {
    ga2d_joint_id id;
    ga2d_body_id a, b;
    int type, collide, limits_known;
    ga2d_real lower, upper;
    void *user;
} fsw_joint;

/* A growing byte buffer (snapshots). */
typedef struct fsw_buf { unsigned char *p; size_t n, cap; } fsw_buf;

typedef struct fsw_state fsw_state;

/* The pre-solve callback's context, one per world (a twin has its own):
   its answers depend on the mode and the two ids only, so that two worlds
   loaded from one snapshot decide alike. */
typedef struct fsw_cb {
    fsw_state *s; /* the harness, for its own world; NULL for a twin */
    ga2d_world *w;
    int mode;     /* 0 accept, 1 by the ids, 2 refuse */
    int probe;    /* try every kind of change from inside */
    int scribble; /* write garbage through the manifold (its own world's only: a twin's answers must come out alike) */
    long calls;
} fsw_cb;

struct fsw_state {
    fw_state base; /* the world harness's state: first, so its callbacks take ours */
    fsw_shape shapes[FSW_MAX_SHAPES];
    int nshapes;
    fsw_chain chains[FSW_MAX_CHAINS];
    int nchains;
    ga2d_sensor_event open[FSW_MAX_OPEN];
    int nopen, open_lost; /* open_lost: more pairs than the table holds */
    fsw_cb cb;
    ga2d_world_def def;   /* as the world was made: for the worlds snapshots go to */
    fsw_buf ckpt;         /* a checkpoint, for rollbacks */
    int pending_oom;      /* an allocation failed in a destruction: the next step may say so */
    int has_pre_solve;
    ga2d_real hit_threshold;
    int ckpt_substeps, ckpt_rk4, ckpt_passes; /* what the harness knew of the world at the checkpoint */
    int mass_set;         /* a body's mass was set by hand (or kept by a destroy): shapes' sums no longer show */
    int field_on;         /* the world has fw_field as its force callback (a snapshot does not carry it) */
    int heavy;            /* a heavy shape was tried: a body's sums may be near the range (MASS_OVERFLOW may follow) */
    int contained;        /* a step contained a body (NOT_FINITE) */
    fsw_joint joints[FSW_MAX_JOINTS];
    int njoints, joints_lost; /* joints_lost: more joints than the table holds (the count is not checked) */
    int ccd_known, ccd_on; /* the continuous switch as the harness set it (unknown after a load) */
};

static void fsw_round_trip(fsw_state *s);
static void fsw_check_joints(fsw_state *s, int after_step);
static void fsw_forget_joints(fsw_state *s);
static void fsw_q_check_continuous(fsw_state *s);
static ga2d_aabb fsw_q_shape_box(ga2d_world *w, ga2d_shape_id id, double *S);
static int fsw_q_in_tree_box(ga2d_world *w, ga2d_shape_id id, double S);
static ga2d_real fsw_q_never(ga2d_shape_id shape, ga2d_vec p, ga2d_vec n, ga2d_real f, void *ctx);
static int fsw_q_never_overlap(ga2d_shape_id shape, void *ctx);

/* ------------------------------------------------------------- buffers */
static int fsw_save(const ga2d_world *w, fsw_buf *b)
{
    size_t n = ga2d_world_snapshot_size(w);
    if (n > b->cap) {
        unsigned char *p = (unsigned char *)realloc(b->p, n);
        if (!p) return 0;
        b->p = p;
        b->cap = n;
    }
    b->n = n;
    return ga2d_world_snapshot_save(w, b->p, b->cap) == GA2D_OK;
}

static int fsw_same(const fsw_buf *a, const fsw_buf *b) { return a->n == b->n && memcmp(a->p, b->p, a->n) == 0; }

/* Before a call that may be refused: the world's bytes (0 if the save
   itself ran out of memory: then nothing is compared). */
typedef struct fsw_guard { fsw_buf before; int ok; long failures; } fsw_guard;

static void fsw_guard_begin(fsw_state *s, fsw_guard *g)
{
    memset(g, 0, sizeof *g);
    g->ok = fsw_save(s->base.w, &g->before);
    g->failures = s->base.alloc.failures;
}

/* After it: refused, the world is the same bytes. */
static void fsw_guard_end(fsw_state *s, fsw_guard *g, ga2d_result r)
{
    if (r != GA2D_OK && g->ok) {
        fsw_buf after;
        memset(&after, 0, sizeof after);
        if (fsw_save(s->base.w, &after)) FUZZ_CHECK(fsw_same(&g->before, &after));
        free(after.p);
    }
    if (r == GA2D_ERR_OUT_OF_MEMORY) FUZZ_CHECK(s->base.alloc.failures != g->failures);
    free(g->before.p);
}

/* ---------------------------------------------------------------- table */
static fsw_shape fsw_lookup(const fsw_state *s, ga2d_shape_id id)
{
    fsw_shape none;
    int i;
    for (i = 0; i < s->nshapes; ++i)
        if (ga2d_shape_id_equal(s->shapes[i].id, id)) return s->shapes[i];
    memset(&none, 0, sizeof none);
    none.type = -1;
    none.sensor_events = 1; /* the default shape def's */
    return none;
}

/* A new shape's entry: an id seen before (a checkpoint brought an old one
   back) takes the old entry's place. */
static void fsw_remember(fsw_state *s, const fsw_shape *e)
{
    int i;
    for (i = 0; i < s->nshapes; ++i)
        if (ga2d_shape_id_equal(s->shapes[i].id, e->id)) {
            s->shapes[i] = *e;
            return;
        }
    if (s->nshapes < FSW_MAX_SHAPES) s->shapes[s->nshapes++] = *e;
}

/* The shape an operation acts on: a tracked one (live or not), the null
   id, or a forged one. */
static ga2d_shape_id fsw_shape_id(fsw_state *s)
{
    unsigned k = fz_u8(&s->base.rd);
    ga2d_shape_id id = ga2d_shape_id_null();
    if (s->nshapes > 0 && k < 224) return s->shapes[k % (unsigned)s->nshapes].id;
    if (k >= 240) {
        id.index1 = (uint32_t)(k - 239);
        id.generation = (uint32_t)fz_u8(&s->base.rd) | ((k & 1) ? 0x80000000u : 0);
    }
    return id;
}

/* Every live sensor's overlaps are the open pairs, afresh (after a load,
   or a step that ran out of memory). */
static void fsw_resync(fsw_state *s)
{
    int i, j, n;
    ga2d_shape_id buf[FSW_SCRATCH];
    s->nopen = 0;
    s->open_lost = 0;
    for (i = 0; i < s->nshapes; ++i) {
        if (!s->shapes[i].sensor || !ga2d_shape_is_valid(s->base.w, s->shapes[i].id)) continue;
        n = ga2d_shape_get_sensor_overlaps(s->base.w, s->shapes[i].id, buf, FSW_SCRATCH);
        FUZZ_CHECK(n >= 0);
        for (j = 0; j < n && j < FSW_SCRATCH; ++j) {
            if (s->nopen == FSW_MAX_OPEN) {
                s->open_lost = 1;
                return;
            }
            s->open[s->nopen].sensor = s->shapes[i].id;
            s->open[s->nopen++].visitor = buf[j];
        }
        if (n > FSW_SCRATCH) s->open_lost = 1;
    }
}

static int fsw_find_open(const fsw_state *s, ga2d_shape_id sensor, ga2d_shape_id visitor)
{
    int i;
    for (i = 0; i < s->nopen; ++i)
        if (ga2d_shape_id_equal(s->open[i].sensor, sensor) && ga2d_shape_id_equal(s->open[i].visitor, visitor)) return i;
    return -1;
}

/* Each live sensor's overlaps: live non-sensor shapes on other bodies
   that take sensor events; and (unless the table overflowed) exactly the
   open pairs. */
static void fsw_check_sensors(fsw_state *s)
{
    ga2d_world *w = s->base.w;
    ga2d_shape_id buf[FSW_SCRATCH];
    int i, j, n, total = 0;
    for (i = 0; i < s->nshapes; ++i) {
        const fsw_shape *e = &s->shapes[i];
        if (!e->sensor || !ga2d_shape_is_valid(w, e->id)) {
            FUZZ_CHECK(ga2d_shape_get_sensor_overlaps(w, e->id, buf, FSW_SCRATCH) == 0 || e->sensor);
            continue;
        }
        n = ga2d_shape_get_sensor_overlaps(w, e->id, buf, FSW_SCRATCH);
        FUZZ_CHECK(n >= 0);
        total += n;
        for (j = 0; j < n && j < FSW_SCRATCH; ++j) {
            fsw_shape v = fsw_lookup(s, buf[j]);
            FUZZ_CHECK(ga2d_shape_is_valid(w, buf[j]));
            FUZZ_CHECK(!ga2d_body_id_equal(ga2d_shape_body(w, buf[j]), ga2d_shape_body(w, e->id)));
            FUZZ_CHECK(!v.sensor && v.sensor_events);
            if (!s->open_lost) FUZZ_CHECK(fsw_find_open(s, e->id, buf[j]) >= 0);
        }
    }
    if (!s->open_lost) FUZZ_CHECK(total == s->nopen);
}

/* ---------------------------------------------------------------- steps */
/* What any step that was not refused promises (fw_check_step's, with the
   one difference shapes bring: an allocation that failed in a destruction
   (a sensor's end event) is reported by the next step). */
static void fsw_check_step(fsw_state *s, ga2d_result r, long failures_before)
{
    fw_state *b = &s->base;
    ga2d_body_id bad = ga2d_world_error_body(b->w);
    FUZZ_CHECK(r == GA2D_OK || r == GA2D_ERR_OUT_OF_MEMORY || r == GA2D_ERR_NOT_FINITE);
    if (b->alloc.failures != failures_before) FUZZ_CHECK(r == GA2D_ERR_OUT_OF_MEMORY);
    if (r == GA2D_ERR_OUT_OF_MEMORY) FUZZ_CHECK(b->alloc.failures != failures_before || s->pending_oom);
    if (r == GA2D_OK) FUZZ_CHECK(ga2d_body_id_is_null(bad));
    if (r == GA2D_ERR_NOT_FINITE) FUZZ_CHECK(ga2d_body_is_valid(b->w, bad));
    if (r == GA2D_OK || r == GA2D_ERR_NOT_FINITE) fw_check_finite(b);
}

/* The events of a step that completed: sensor pairs open and close once
   each; hits are finite, fast enough, asked for and not refused. */
static void fsw_check_events(fsw_state *s, int oom)
{
    ga2d_world *w = s->base.w;
    ga2d_sensor_events se = ga2d_world_sensor_events(w);
    ga2d_contact_events ce = ga2d_world_contact_events(w);
    int i;
    FUZZ_CHECK(se.begin_count >= 0 && se.end_count >= 0);
    FUZZ_CHECK(ce.begin_count >= 0 && ce.end_count >= 0 && ce.hit_count >= 0);
    if (oom) {
        fsw_resync(s);
        return;
    }
    for (i = 0; i < se.end_count; ++i) {
        int k = fsw_find_open(s, se.end[i].sensor, se.end[i].visitor);
        FSW_TRACE((stderr, "  sensor end %u/%u\n", se.end[i].sensor.index1, se.end[i].visitor.index1));
        if (!s->open_lost) FUZZ_CHECK(k >= 0); /* an end for what began */
        if (k >= 0) s->open[k] = s->open[--s->nopen];
    }
    for (i = 0; i < se.begin_count; ++i) {
        fsw_shape sensor = fsw_lookup(s, se.begin[i].sensor);
        FSW_TRACE((stderr, "  sensor begin %u/%u\n", se.begin[i].sensor.index1, se.begin[i].visitor.index1));
        FUZZ_CHECK(ga2d_shape_is_valid(w, se.begin[i].sensor) && ga2d_shape_is_valid(w, se.begin[i].visitor));
        FUZZ_CHECK(sensor.sensor);
        FUZZ_CHECK(fsw_find_open(s, se.begin[i].sensor, se.begin[i].visitor) < 0); /* began once */
        if (s->nopen < FSW_MAX_OPEN) {
            s->open[s->nopen].sensor = se.begin[i].sensor;
            s->open[s->nopen++].visitor = se.begin[i].visitor;
        } else {
            s->open_lost = 1;
        }
    }
    fsw_check_sensors(s);
    for (i = 0; i < ce.hit_count; ++i) {
        const ga2d_contact_hit_event *h = &ce.hit[i];
        fsw_shape a = fsw_lookup(s, h->shape_a), b = fsw_lookup(s, h->shape_b);
        double nn = (double)h->normal.x * (double)h->normal.x + (double)h->normal.y * (double)h->normal.y;
        FUZZ_CHECK(ga2d_shape_is_valid(w, h->shape_a) && ga2d_shape_is_valid(w, h->shape_b));
        FUZZ_CHECK(a.hit || b.hit);
        FUZZ_CHECK(fz_finite_vec(h->point) && fz_finite_vec(h->normal) && fz_finite((double)h->approach_speed));
        FUZZ_CHECK((double)h->approach_speed > (double)s->hit_threshold * s->base.units * (1 - 4 * FZ_EPS));
        FUZZ_CHECK(fabs(nn - 1) <= 1e-3);
        /* a contact the pre-solve turned down did not push: no hit */
        if (s->has_pre_solve && s->cb.mode == 2) FUZZ_CHECK(!a.pre_solve && !b.pre_solve);
    }
}

/* A step: fw_step's bounds and checks, with the shapes counted in the
   work budget.  Returns 1 when the step ran. */
static int fsw_step_dt(fsw_state *s, ga2d_real dt, ga2d_result *out)
{
    fw_state *b = &s->base;
    long long steps_before;
    long failures, cost;
    ga2d_result r;
    int i, asleep[FW_MAX_IDS];
    cost = (long)b->substeps * b->passes * (b->rk4 ? 4 : 1) *
           (ga2d_world_get_counters(b->w).body_count + s->nshapes + 8 * s->nchains + 2 * s->njoints + 1);
    if (b->work + cost > FW_WORK_BUDGET) return 0;
    b->work += cost;
    steps_before = ga2d_world_get_counters(b->w).step_count;
    failures = b->alloc.failures;
    s->cb.calls = 0;
    for (i = 0; i < b->nids; ++i)
        asleep[i] = ga2d_body_get_type(b->w, b->ids[i]) == GA2D_BODY_DYNAMIC && !ga2d_body_is_awake(b->w, b->ids[i]);
    r = ga2d_world_step(b->w, dt);
    FSW_TRACE((stderr, "step %g: %s (pre-solve calls %ld)\n", (double)dt, ga2d_result_string(r), s->cb.calls));
    *out = r;
    FUZZ_CHECK((int)r >= 0 && r < GA2D_RESULT_COUNT);
    if (!(fz_finite((double)dt) && dt > 0)) FUZZ_CHECK(r == GA2D_ERR_INVALID_ARGUMENT);
    if (r == GA2D_ERR_INVALID_ARGUMENT || r == GA2D_ERR_TOO_LARGE) {
        if (r == GA2D_ERR_TOO_LARGE) FUZZ_CHECK(fw_step_too_large(b, (double)dt, 0.999));
        FUZZ_CHECK(ga2d_world_get_counters(b->w).step_count == steps_before);
        return 0;
    }
    FUZZ_CHECK(!fw_step_too_large(b, (double)dt, 1.001));
    FUZZ_CHECK(ga2d_world_get_counters(b->w).step_count == steps_before + 1);
    fsw_check_step(s, r, failures);
    fsw_q_check_continuous(s);
    /* the field pushed every tracked body (a torque field_k at least):
       those that slept wake at the step's end */
    if (s->field_on && fz_finite((double)b->field_k) && b->field_k != 0)
        for (i = 0; i < b->nids; ++i)
            if (asleep[i]) FUZZ_CHECK(ga2d_body_is_awake(b->w, b->ids[i]));
    /* a destruction's end event that found no room: this step says so */
    if (s->pending_oom) FUZZ_CHECK(r == GA2D_ERR_OUT_OF_MEMORY);
    s->pending_oom = 0;
    /* (OUT_OF_MEMORY wins over NOT_FINITE: a step that ran out may have
       contained a body too) */
    if (r == GA2D_ERR_NOT_FINITE || r == GA2D_ERR_OUT_OF_MEMORY) s->contained = 1;
    fsw_check_events(s, r == GA2D_ERR_OUT_OF_MEMORY);
    fsw_check_joints(s, 1);
    return 1;
}

static void fsw_step(fsw_state *s)
{
    static const double dts[8] = {1.0 / 60, 1.0 / 30, 1.0 / 120, 1.0 / 240, 0, -1.0 / 60, 1e-30, 10};
    unsigned k = fz_u8(&s->base.rd);
    ga2d_real dt = k < 220 ? fz_narrow(dts[k % 4]) : (k < 248 ? fz_narrow(dts[k % 8]) : fz_real(&s->base.rd, 1));
    ga2d_result r;
    (void)fsw_step_dt(s, dt, &r);
}

/* ------------------------------------------------------------ pre-solve */
/* Every kind of change, from inside the step: each refused with LOCKED
   (the null id for the makers that return ids), and nothing changed
   that a getter shows. */
static void fsw_probe_locked(fsw_cb *cb, ga2d_shape_id a)
{
    ga2d_world *w = cb->w;
    ga2d_body_id body = ga2d_shape_body(w, a);
    ga2d_world_counters before = ga2d_world_get_counters(w);
    size_t size = ga2d_world_snapshot_size(w);
    ga2d_filter f = ga2d_shape_filter(w, a);
    ga2d_vec v = ga2d_body_velocity(w, body);
    ga2d_shape_def sd = ga2d_default_shape_def();
    ga2d_body_def bd = ga2d_default_body_def();
    ga2d_chain_def cd = ga2d_default_chain_def();
    ga2d_geometry g;
    ga2d_shape_id sid;
    ga2d_chain_id cid;
    ga2d_circle c;
    ga2d_vec pts[3];
    unsigned char buf[64];
    ga2d_debug_draw dd = ga2d_default_debug_draw();
    c.center = ga2d_vec_make(0, 0);
    c.radius = (ga2d_real)0.5;
    memset(&g, 0, sizeof g);
    g.type = GA2D_SHAPE_CIRCLE;
    g.as.circle = c;
    pts[0] = ga2d_vec_make(0, 0);
    pts[1] = ga2d_vec_make(1, 0);
    pts[2] = ga2d_vec_make(1, 1);
    cd.points = pts;
    cd.count = 3;
    bd.polygon = ga2d_polygon_box(1, 1);
    FUZZ_CHECK(ga2d_world_step(w, (ga2d_real)(1.0 / 60)) == GA2D_ERR_LOCKED);
    FUZZ_CHECK(ga2d_shape_create_checked(w, body, &sd, &g, &sid) == GA2D_ERR_LOCKED && ga2d_shape_id_is_null(sid));
    FUZZ_CHECK(ga2d_shape_id_is_null(ga2d_shape_create_circle(w, body, &sd, &c)));
    FUZZ_CHECK(ga2d_shape_destroy(w, a, 1) == GA2D_ERR_LOCKED);
    FUZZ_CHECK(ga2d_shape_set_friction(w, a, 1) == GA2D_ERR_LOCKED);
    FUZZ_CHECK(ga2d_shape_set_restitution(w, a, 1) == GA2D_ERR_LOCKED);
    FUZZ_CHECK(ga2d_shape_set_filter(w, a, ga2d_default_filter()) == GA2D_ERR_LOCKED);
    FUZZ_CHECK(ga2d_chain_create_checked(w, body, &cd, &cid) == GA2D_ERR_LOCKED && cid.index1 == 0);
    cid.index1 = 1;
    cid.generation = 1;
    FUZZ_CHECK(ga2d_chain_destroy(w, cid) == GA2D_ERR_LOCKED);
    FUZZ_CHECK(ga2d_body_id_is_null(ga2d_body_create(w, &bd)));
    FUZZ_CHECK(ga2d_body_destroy(w, body) == GA2D_ERR_LOCKED);
    FUZZ_CHECK(ga2d_body_set_velocity(w, body, ga2d_vec_make(1, 0)) == GA2D_ERR_LOCKED);
    FUZZ_CHECK(ga2d_body_apply_force(w, body, ga2d_vec_make(1, 0), ga2d_vec_make(0, 0)) == GA2D_ERR_LOCKED);
    FUZZ_CHECK(ga2d_body_apply_force_to_center(w, body, ga2d_vec_make(1, 0)) == GA2D_ERR_LOCKED);
    FUZZ_CHECK(ga2d_body_apply_torque(w, body, 1) == GA2D_ERR_LOCKED);
    FUZZ_CHECK(ga2d_body_apply_impulse(w, body, ga2d_vec_make(1, 0), ga2d_vec_make(0, 0)) == GA2D_ERR_LOCKED);
    FUZZ_CHECK(ga2d_body_set_awake(w, body, 0) == GA2D_ERR_LOCKED);
    FUZZ_CHECK(ga2d_world_set_gravity(w, ga2d_vec_make(0, 0)) == GA2D_ERR_LOCKED);
    FUZZ_CHECK(ga2d_world_compact(w) == GA2D_ERR_LOCKED);
    FUZZ_CHECK(ga2d_world_snapshot_save(w, buf, sizeof buf) == GA2D_ERR_LOCKED);
    FUZZ_CHECK(ga2d_world_snapshot_load(w, buf, sizeof buf) == GA2D_ERR_LOCKED);
    FUZZ_CHECK(ga2d_world_draw(w, &dd) == GA2D_ERR_LOCKED);
    {
        /* queries, the continuous switch and bullets (issue 25) */
        ga2d_ray_result rr;
        ga2d_aabb box;
        ga2d_shape_proxy px = ga2d_make_proxy(pts, 1, (ga2d_real)0.5);
        box.lower = pts[0];
        box.upper = pts[2];
        FUZZ_CHECK(ga2d_world_cast_ray_closest_checked(w, pts[0], pts[2], f, &rr) == GA2D_ERR_LOCKED);
        FUZZ_CHECK(!ga2d_world_cast_ray_closest(w, pts[0], pts[2], f).hit);
        FUZZ_CHECK(ga2d_world_cast_ray(w, pts[0], pts[2], f, fsw_q_never, NULL) == GA2D_ERR_LOCKED);
        FUZZ_CHECK(ga2d_world_overlap_aabb(w, box, f, fsw_q_never_overlap, NULL) == GA2D_ERR_LOCKED);
        FUZZ_CHECK(ga2d_world_overlap_point(w, pts[1], f, fsw_q_never_overlap, NULL) == GA2D_ERR_LOCKED);
        FUZZ_CHECK(ga2d_world_overlap_shape(w, &px, ga2d_transform_identity(), f, fsw_q_never_overlap, NULL) == GA2D_ERR_LOCKED);
        FUZZ_CHECK(ga2d_world_cast_shape(w, &px, ga2d_transform_identity(), pts[2], f, fsw_q_never, NULL) == GA2D_ERR_LOCKED);
        FUZZ_CHECK(ga2d_world_enable_continuous(w, 1) == GA2D_ERR_LOCKED);
        FUZZ_CHECK(ga2d_body_set_bullet(w, body, 1) == GA2D_ERR_LOCKED);
        FUZZ_CHECK(ga2d_world_get_bodies(w, NULL, 0) == before.body_count);
    }
    {
        /* joints: every maker, the destroy and the setters (on a tracked
           joint, or a forged id: LOCKED comes first) */
        ga2d_revolute_joint_def rj = ga2d_default_revolute_joint_def();
        ga2d_distance_joint_def dj = ga2d_default_distance_joint_def();
        ga2d_weld_joint_def wj = ga2d_default_weld_joint_def();
        ga2d_motor_joint_def mj = ga2d_default_motor_joint_def();
        ga2d_joint_id jid;
        jid.index1 = 1;
        jid.generation = 1;
        if (cb->s && cb->s->njoints > 0) jid = cb->s->joints[cb->calls % (unsigned)cb->s->njoints].id;
        rj.body_a = dj.body_a = wj.body_a = mj.body_a = body;
        rj.body_b = dj.body_b = wj.body_b = mj.body_b = ga2d_joint_body_b(w, jid);
        FUZZ_CHECK(ga2d_revolute_joint_create_checked(w, &rj, &jid) == GA2D_ERR_LOCKED && ga2d_joint_id_is_null(jid));
        FUZZ_CHECK(ga2d_joint_id_is_null(ga2d_distance_joint_create(w, &dj)));
        FUZZ_CHECK(ga2d_weld_joint_create_checked(w, &wj, &jid) == GA2D_ERR_LOCKED && ga2d_joint_id_is_null(jid));
        FUZZ_CHECK(ga2d_motor_joint_create_checked(w, &mj, &jid) == GA2D_ERR_LOCKED);
        jid.index1 = 1;
        jid.generation = 1;
        if (cb->s && cb->s->njoints > 0) jid = cb->s->joints[cb->calls % (unsigned)cb->s->njoints].id;
        FUZZ_CHECK(ga2d_joint_destroy(w, jid) == GA2D_ERR_LOCKED);
        FUZZ_CHECK(ga2d_revolute_joint_set_limits(w, jid, -1, 1) == GA2D_ERR_LOCKED);
        FUZZ_CHECK(ga2d_revolute_joint_enable_motor(w, jid, 1) == GA2D_ERR_LOCKED);
        FUZZ_CHECK(ga2d_distance_joint_set_length(w, jid, 2) == GA2D_ERR_LOCKED);
        FUZZ_CHECK(ga2d_distance_joint_set_spring(w, jid, 1, 1) == GA2D_ERR_LOCKED);
        FUZZ_CHECK(ga2d_weld_joint_set_angular_spring(w, jid, 1, 1) == GA2D_ERR_LOCKED);
        FUZZ_CHECK(ga2d_motor_joint_set_linear_offset(w, jid, ga2d_vec_make(1, 0)) == GA2D_ERR_LOCKED);
        FUZZ_CHECK(ga2d_motor_joint_set_max_torque(w, jid, (ga2d_real)NAN) == GA2D_ERR_LOCKED);
    }
    {
        ga2d_world_counters after = ga2d_world_get_counters(w);
        ga2d_filter f2 = ga2d_shape_filter(w, a);
        ga2d_vec v2 = ga2d_body_velocity(w, body);
        FUZZ_CHECK(after.body_count == before.body_count && after.pair_count == before.pair_count);
        FUZZ_CHECK(after.joint_count == before.joint_count);
        FUZZ_CHECK(ga2d_world_snapshot_size(w) == size);
        FUZZ_CHECK(ga2d_shape_is_valid(w, a));
        FUZZ_CHECK(memcmp(&f, &f2, sizeof f) == 0 && memcmp(&v, &v2, sizeof v) == 0);
    }
}

/* The answer: a function of the mode and the two ids. */
static int fsw_decide(int mode, ga2d_shape_id a, ga2d_shape_id b)
{
    if (mode == 0) return 1;
    if (mode == 2) return 0;
    return ((a.index1 * 7u + b.index1 * 3u) & 3u) != 0;
}

static int fsw_pre_solve(ga2d_shape_id a, ga2d_shape_id b, const ga2d_manifold *m, void *ctx)
{
    fsw_cb *cb = (fsw_cb *)ctx;
    ga2d_world *w = cb->w;
    ++cb->calls;
    FUZZ_CHECK(m != NULL && m->count >= 1 && m->count <= 2);
    FUZZ_CHECK(fz_finite_vec(m->normal));
    FUZZ_CHECK(ga2d_shape_is_valid(w, a) && ga2d_shape_is_valid(w, b));
    FUZZ_CHECK(!ga2d_body_id_equal(ga2d_shape_body(w, a), ga2d_shape_body(w, b)));
    FUZZ_CHECK(a.index1 < b.index1); /* A's slot before B's */
    if (cb->s) {
        fsw_shape ea = fsw_lookup(cb->s, a), eb = fsw_lookup(cb->s, b);
        FUZZ_CHECK(ea.pre_solve || eb.pre_solve);
    }
    /* the first calls of each step try every change */
    if (cb->probe && cb->calls <= 2) fsw_probe_locked(cb, a);
    if (cb->scribble && cb->s) {
        /* what a careless callback may do: the manifold is the callback's
           copy, so a replay in a twin that writes nothing ends in the same
           bytes (fsw_replay) */
        ga2d_manifold *g = (ga2d_manifold *)m;
        int k;
        g->count = (int)(cb->calls % 3 == 0 ? 1000 : cb->calls % 3 == 1 ? -5 : 2);
        g->normal = ga2d_vec_make((ga2d_real)NAN, (ga2d_real)INFINITY);
        for (k = 0; k < 2; ++k) {
            g->points[k].point = g->points[k].anchor_a = ga2d_vec_make((ga2d_real)NAN, (ga2d_real)-INFINITY);
            g->points[k].separation = g->points[k].normal_impulse = (ga2d_real)NAN;
            g->points[k].id = 0xFFFFFFFFu;
        }
    }
    return fsw_decide(cb->mode, a, b);
}

/* ------------------------------------------------------------- shapes */
/* A shape def: clean (ordinary materials, the flags any way) or wild. */
static ga2d_shape_def fsw_shape_def(fsw_state *s, int *clean)
{
    fz_reader *r = &s->base.rd;
    ga2d_shape_def d = ga2d_default_shape_def();
    unsigned flags = fz_u8(r), more = fz_u8(r);
    int wild = (flags & 7) == 0;
    *clean = !wild;
    if (flags & 8) d.density = wild ? fz_real(r, 4) : ((more & 1) ? 0 : fz_narrow((double)(1 + fz_u8(r) % 64) / 16));
    if (flags & 16) {
        d.friction = wild ? fz_real(r, 1) : fz_narrow((double)fz_u8(r) / 128);
        d.restitution = wild ? fz_real(r, 1) : fz_narrow((double)fz_u8(r) / 256);
    }
    if (flags & 32) {
        d.filter.category_bits = (uint32_t)1 << (fz_u8(r) & 31);
        d.filter.mask_bits = fz_u8(r) < 128 ? 0xFFFFFFFFu : fz_u32(r);
        d.filter.group_index = (int32_t)(int8_t)fz_u8(r) % 4;
    }
    d.is_sensor = (more >> 1) & 1;
    d.enable_sensor_events = ((more >> 2) & 3) != 0;
    d.enable_pre_solve_events = (more >> 4) & 1;
    d.enable_hit_events = (more >> 5) & 1;
    if (flags & 64) d.tangent_speed = wild ? fz_real(r, 4) : fz_narrow((double)(int8_t)fz_u8(r) / 32);
    if ((flags & 128) && !wild) d.rolling_resistance = fz_narrow((double)fz_u8(r) / 512);
    d.user_data = (more & 64) ? &s->base.tag : NULL;
    if ((more & 0xC0) == 0xC0) {
        /* by hand: its zeros are the defaults */
        int sensor = d.is_sensor;
        memset(&d, 0, sizeof d);
        d.is_sensor = sensor;
    }
    return d;
}

/* A polygon for a shape: a maker's (clean) or anything. */
static ga2d_polygon fsw_polygon(fsw_state *s, int *clean)
{
    fz_reader *r = &s->base.rd;
    ga2d_polygon p;
    int k = fz_pick(r, 8);
    *clean = 1;
    if (k < 2) {
        /* one read a statement: arguments are evaluated in no set order */
        ga2d_real hw = fz_narrow((double)(4 + fz_u8(r) % 60) / 32);
        p = ga2d_polygon_box(hw, fz_narrow((double)(4 + fz_u8(r) % 60) / 32));
    } else if (k < 4) {
        ga2d_real hw = fz_narrow((double)(4 + fz_u8(r) % 60) / 32), hh = fz_narrow((double)(4 + fz_u8(r) % 60) / 32);
        p = ga2d_polygon_rounded_box(hw, hh, (hw < hh ? hw : hh) * (ga2d_real)(fz_u8(r) % 200) / 256);
    } else if (k < 6) {
        int count = 3 + fz_pick(r, GA2D_MAX_POLYGON_VERTICES - 2);
        p = ga2d_polygon_regular(count, fz_narrow((double)(4 + fz_u8(r) % 60) / 32));
        if (fz_u8(r) < 64) p.radius = fz_narrow((double)(fz_u8(r) % 64) / 256);
    } else {
        /* fw_polygon's: boxes, regular ones, hulls of points, hand-filled
           structs; with any radius */
        p = fw_polygon(&s->base, fz_u8(r) < 64);
        if (fz_u8(r) < 64) p.radius = fz_real(r, 1);
        *clean = 0;
    }
    return p;
}

/* A point in a body's frame: ordinary (within 2) or anything. */
static ga2d_vec fsw_vec(fsw_state *s, int wild)
{
    fz_reader *r = &s->base.rd;
    ga2d_vec v;
    if (wild) return fw_vec(&s->base, 2, 1);
    v.x = fz_narrow((double)(int8_t)fz_u8(r) / 64);
    v.y = fz_narrow((double)(int8_t)fz_u8(r) / 64);
    return v;
}

/* Two ends at least 1/16 apart. */
static void fsw_ends(fsw_state *s, ga2d_vec *p1, ga2d_vec *p2)
{
    fz_reader *r = &s->base.rd;
    double a = (double)fz_u8(r) * (6.283185307179586 / 256), len = (double)(4 + fz_u8(r) % 60) / 32;
    *p1 = fsw_vec(s, 0);
    *p2 = ga2d_vec_add(*p1, ga2d_vec_make(fz_narrow(len * cos(a)), fz_narrow(len * sin(a))));
}

/* A geometry: clean (ordinary sizes, every type), wild, degenerate, a
   lone chain segment, or a type out of range. */
static void fsw_geometry(fsw_state *s, ga2d_geometry *g, int *clean)
{
    fz_reader *r = &s->base.rd;
    int k = fz_pick(r, 16);
    memset(g, 0, sizeof *g);
    *clean = 1;
    if (k < 3) {
        g->type = GA2D_SHAPE_CIRCLE;
        g->as.circle.center = fsw_vec(s, 0);
        g->as.circle.radius = fz_narrow((double)(4 + fz_u8(r) % 60) / 64);
    } else if (k < 6) {
        g->type = GA2D_SHAPE_CAPSULE;
        fsw_ends(s, &g->as.capsule.center1, &g->as.capsule.center2);
        g->as.capsule.radius = fz_narrow((double)(2 + fz_u8(r) % 40) / 64);
    } else if (k < 10) {
        g->type = GA2D_SHAPE_POLYGON;
        g->as.polygon = fsw_polygon(s, clean);
    } else if (k < 12) {
        g->type = GA2D_SHAPE_SEGMENT;
        fsw_ends(s, &g->as.segment.point1, &g->as.segment.point2);
    } else if (k == 12) {
        ga2d_chain_segment *c = &g->as.chain_segment;
        g->type = GA2D_SHAPE_CHAIN_SEGMENT;
        fsw_ends(s, &c->segment.point1, &c->segment.point2);
        fsw_ends(s, &c->ghost2, &c->ghost1);
        c->ghost1 = ga2d_vec_add(c->segment.point1, ga2d_vec_sub(c->ghost1, c->ghost2));
        c->ghost2 = ga2d_vec_add(c->segment.point2, ga2d_vec_sub(c->ghost2, c->segment.point1));
        *clean = 0;
    } else if (k == 13) {
        /* anything, in any of the four types */
        g->type = (ga2d_shape_type)fz_pick(r, 4);
        *clean = 0;
        switch ((int)g->type) {
        case GA2D_SHAPE_CIRCLE:
            g->as.circle.center = fsw_vec(s, 1);
            g->as.circle.radius = fz_real(r, 1);
            break;
        case GA2D_SHAPE_CAPSULE:
            g->as.capsule.center1 = fsw_vec(s, 1);
            g->as.capsule.center2 = fsw_vec(s, 1);
            g->as.capsule.radius = fz_real(r, 1);
            break;
        case GA2D_SHAPE_POLYGON: g->as.polygon = fw_polygon(&s->base, 1); break;
        default:
            g->as.segment.point1 = fsw_vec(s, 1);
            g->as.segment.point2 = fsw_vec(s, 1);
            break;
        }
    } else if (k == 14) {
        /* degenerate on purpose: ends that coincide or nearly, no radius,
           a negative one, a point beyond GA2D_MAX_COORDINATE */
        int d = fz_pick(r, 6);
        ga2d_vec p = fsw_vec(s, 0);
        *clean = 0;
        g->type = d < 2 ? GA2D_SHAPE_CAPSULE : d < 4 ? GA2D_SHAPE_SEGMENT : GA2D_SHAPE_CIRCLE;
        if (d < 4) {
            ga2d_vec q = (d & 1) ? ga2d_vec_make(p.x + p.x * (ga2d_real)FZ_EPS, p.y) : p;
            if (d < 2) {
                g->as.capsule.center1 = p;
                g->as.capsule.center2 = q;
                g->as.capsule.radius = (ga2d_real)0.25;
            } else {
                g->as.segment.point1 = p;
                g->as.segment.point2 = q;
            }
        } else {
            g->as.circle.center = d == 4 ? p : ga2d_vec_make(fz_narrow(2.0 * (double)GA2D_MAX_COORDINATE), p.y);
            g->as.circle.radius = d == 4 ? (fz_u8(r) & 1 ? 0 : (ga2d_real)-0.25) : (ga2d_real)0.5;
        }
    } else {
        g->type = (ga2d_shape_type)(GA2D_SHAPE_TYPE_COUNT + fz_pick(r, 3));
        g->as.circle.radius = 1;
        *clean = 0;
    }
}

/* A heavy shape: the density a power of two below the largest real, the
   geometry moved out to a fraction of GA2D_MAX_COORDINATE, so that shapes
   each accepted sum past the range on one body (the mass, the centre's
   moment, the parallel-axis inertia). */
static void fsw_heavy(fsw_state *s, ga2d_shape_def *d, ga2d_geometry *g)
{
    fz_reader *r = &s->base.rd;
    unsigned e = fz_u8(r), j = fz_u8(r);
    double off = (double)GA2D_MAX_COORDINATE * (double)((int)(j % 17) - 8) / 8;
    ga2d_vec t;
    int i;
    d->density = fz_narrow(ldexp(FZ_REAL_MAX, -(int)(1 + e % 96)));
    /* within the bound: the shapes reach 4 from their centre at most */
    off = off > 0 ? off - 4 : off < 0 ? off + 4 : 0;
    t = (j & 32) ? ga2d_vec_make(0, fz_narrow(off)) : ga2d_vec_make(fz_narrow(off), 0);
    switch ((int)g->type) {
    case GA2D_SHAPE_CIRCLE: g->as.circle.center = ga2d_vec_add(g->as.circle.center, t); break;
    case GA2D_SHAPE_CAPSULE:
        g->as.capsule.center1 = ga2d_vec_add(g->as.capsule.center1, t);
        g->as.capsule.center2 = ga2d_vec_add(g->as.capsule.center2, t);
        break;
    case GA2D_SHAPE_POLYGON:
        for (i = 0; i < g->as.polygon.count && i < GA2D_MAX_POLYGON_VERTICES; ++i)
            g->as.polygon.vertices[i] = ga2d_vec_add(g->as.polygon.vertices[i], t);
        break;
    default: break;
    }
    s->heavy = 1;
}

/* Whether a body's sums may pass the range: heavy shapes were made, or
   the body spins so fast that its centre's velocity (v + (C' - C) Omega,
   C' - C up to 6 M away) may. */
static int fsw_overflow_plausible(const fsw_state *s, ga2d_body_id body)
{
    double w = fabs((double)ga2d_body_angular_velocity(s->base.w, body));
    return s->heavy || !(w < FZ_REAL_MAX / (8 * (double)GA2D_MAX_COORDINATE));
}

/* Makes a shape on a tracked body, a destroyed one or a forged id, by a
   typed maker or ga2d_shape_create_checked, and checks what it promises. */
static void fsw_shape_create(fsw_state *s)
{
    fw_state *b = &s->base;
    ga2d_world *w = b->w;
    ga2d_body_id body = fw_id(b);
    int clean_def, clean_geo, valid = ga2d_body_is_valid(w, body), btype = (int)ga2d_body_get_type(w, body);
    int how = fz_pick(&b->rd, 3), nbefore, nafter, must_ok;
    ga2d_shape_def d = fsw_shape_def(s, &clean_def);
    ga2d_geometry g;
    ga2d_shape_id id = ga2d_shape_id_null(), list[FSW_SCRATCH];
    ga2d_mass mass_before = ga2d_body_mass_data(w, body);
    ga2d_result r;
    fsw_guard gd;
    fsw_geometry(s, &g, &clean_geo);
    if (fz_u8(&b->rd) < 24) {
        fsw_heavy(s, &d, &g);
        clean_def = 0;
    }
    if (s->nshapes >= FSW_MAX_SHAPES) return;
    nbefore = ga2d_body_get_shapes(w, body, list, FSW_SCRATCH);
    fsw_guard_begin(s, &gd);
    if (how == 0 && (int)g.type <= GA2D_SHAPE_SEGMENT) {
        /* the typed makers say nothing but the id */
        switch ((int)g.type) {
        case GA2D_SHAPE_CIRCLE: id = ga2d_shape_create_circle(w, body, &d, &g.as.circle); break;
        case GA2D_SHAPE_CAPSULE: id = ga2d_shape_create_capsule(w, body, &d, &g.as.capsule); break;
        case GA2D_SHAPE_POLYGON: id = ga2d_shape_create_polygon(w, body, &d, &g.as.polygon); break;
        default: id = ga2d_shape_create_segment(w, body, &d, &g.as.segment); break;
        }
        r = ga2d_shape_id_is_null(id) ? GA2D_ERR_INVALID_ARGUMENT : GA2D_OK;
    } else {
        r = ga2d_shape_create_checked(w, body, &d, &g, &id);
        FUZZ_CHECK((int)r >= 0 && r < GA2D_RESULT_COUNT);
        FUZZ_CHECK((r == GA2D_OK) == !ga2d_shape_id_is_null(id));
        FUZZ_CHECK(r != GA2D_ERR_LOCKED && r != GA2D_ERR_BAD_SNAPSHOT && r != GA2D_ERR_BUFFER_TOO_SMALL);
        if (!valid) FUZZ_CHECK(r == GA2D_ERR_STALE_ID || !clean_def);
    }
    FSW_TRACE((stderr, "shape create type %d on %u (valid %d type %d) how %d sensor %d: %s -> %u\n", (int)g.type, body.index1,
               valid, btype, how, d.is_sensor, ga2d_result_string(r), id.index1));
    /* what must be refused, and what must be made */
    if (!valid || (int)g.type > GA2D_SHAPE_CHAIN_SEGMENT ||
        (btype == GA2D_BODY_DYNAMIC && ((int)g.type == GA2D_SHAPE_SEGMENT || (int)g.type == GA2D_SHAPE_CHAIN_SEGMENT)))
        FUZZ_CHECK(r != GA2D_OK);
    if ((int)g.type == GA2D_SHAPE_CHAIN_SEGMENT) FUZZ_CHECK(r != GA2D_OK);
    must_ok = valid && clean_def && clean_geo && (int)g.type <= GA2D_SHAPE_SEGMENT &&
              !(btype == GA2D_BODY_DYNAMIC && (int)g.type == GA2D_SHAPE_SEGMENT) && b->alloc.failures == gd.failures;
    /* a clean shape on a body whose sums are near the range may pass it */
    if (must_ok) FUZZ_CHECK(r == GA2D_OK || (r == GA2D_ERR_MASS_OVERFLOW && fsw_overflow_plausible(s, body)));
    if (r == GA2D_ERR_MASS_OVERFLOW) FUZZ_CHECK(fsw_overflow_plausible(s, body));
    fsw_guard_end(s, &gd, r);
    nafter = ga2d_body_get_shapes(w, body, list, FSW_SCRATCH);
    if (r != GA2D_OK) {
        FUZZ_CHECK(nafter == nbefore);
        return;
    }
    {
        ga2d_shape_def rd = d;
        ga2d_geometry got = ga2d_shape_geometry(w, id);
        ga2d_mass mass = ga2d_body_mass_data(w, body);
        fsw_shape e;
        int stamped = d.internal_cookie == GA2D_DEF_COOKIE;
        if (!stamped) rd = ga2d_default_shape_def(), rd.is_sensor = d.is_sensor;
        FUZZ_CHECK(ga2d_shape_is_valid(w, id) && ga2d_body_id_equal(ga2d_shape_body(w, id), body));
        FUZZ_CHECK((int)ga2d_shape_get_type(w, id) == (int)g.type && (int)got.type == (int)g.type);
        FUZZ_CHECK(ga2d_shape_user_data(w, id) == (stamped ? d.user_data : NULL));
        if (stamped) {
            ga2d_filter f = ga2d_shape_filter(w, id);
            FUZZ_CHECK(memcmp(&f, &d.filter, sizeof f) == 0);
        }
        switch ((int)g.type) {
        case GA2D_SHAPE_CIRCLE: FUZZ_CHECK(memcmp(&got.as.circle, &g.as.circle, sizeof g.as.circle) == 0); break;
        case GA2D_SHAPE_CAPSULE: FUZZ_CHECK(memcmp(&got.as.capsule, &g.as.capsule, sizeof g.as.capsule) == 0); break;
        case GA2D_SHAPE_SEGMENT: FUZZ_CHECK(memcmp(&got.as.segment, &g.as.segment, sizeof g.as.segment) == 0); break;
        case GA2D_SHAPE_POLYGON:
            FUZZ_CHECK(got.as.polygon.count == g.as.polygon.count && got.as.polygon.radius == g.as.polygon.radius);
            FUZZ_CHECK(memcmp(got.as.polygon.vertices, g.as.polygon.vertices,
                              (size_t)g.as.polygon.count * sizeof g.as.polygon.vertices[0]) == 0);
            break;
        default: break;
        }
        FUZZ_CHECK(nafter == nbefore + 1 && (nafter > FSW_SCRATCH || ga2d_shape_id_equal(list[nafter - 1], id)));
        if (btype == GA2D_BODY_DYNAMIC) {
            FUZZ_CHECK(fz_finite((double)mass.mass) && mass.mass > 0 && fz_finite((double)mass.inertia) && mass.inertia >= 0);
            FUZZ_CHECK(fz_finite_vec(mass.center));
            /* a sensor, or a shape of density 0, adds no mass (appended to
               a body that had shapes: its zero terms change no sum) */
            if ((rd.is_sensor || rd.density == 0) && nbefore > 0 && !s->mass_set)
                FUZZ_CHECK(mass.mass == mass_before.mass && mass.inertia == mass_before.inertia &&
                           mass.center.x == mass_before.center.x && mass.center.y == mass_before.center.y);
        }
        memset(&e, 0, sizeof e);
        e.id = id;
        e.body = body;
        e.type = (int)g.type;
        e.sensor = rd.is_sensor != 0;
        e.sensor_events = rd.enable_sensor_events != 0;
        e.pre_solve = rd.enable_pre_solve_events != 0;
        e.hit = rd.enable_hit_events != 0;
        fsw_remember(s, &e);
        /* whatever a world accepted, its snapshot loads */
        if (s->heavy && fz_u8(&b->rd) < 64) fsw_round_trip(s);
    }
}

/* Destroys a shape (a tracked one, a chain's segment, null or forged). */
static void fsw_shape_destroy(fsw_state *s)
{
    fw_state *b = &s->base;
    ga2d_world *w = b->w;
    ga2d_shape_id id;
    int update = fz_u8(&b->rd) & 1, valid, n, chain_seg;
    ga2d_body_id body;
    ga2d_mass before;
    ga2d_result r;
    fsw_guard gd;
    if (s->nchains > 0 && fz_u8(&b->rd) < 48) {
        const fsw_chain *c = &s->chains[fz_pick(&b->rd, s->nchains)];
        id = c->segments[fz_pick(&b->rd, c->n)];
    } else {
        id = fsw_shape_id(s);
    }
    valid = ga2d_shape_is_valid(w, id);
    chain_seg = valid && ga2d_shape_get_type(w, id) == GA2D_SHAPE_CHAIN_SEGMENT;
    body = ga2d_shape_body(w, id);
    before = ga2d_body_mass_data(w, body);
    n = ga2d_body_get_shapes(w, body, NULL, 0);
    fsw_guard_begin(s, &gd);
    r = ga2d_shape_destroy(w, id, update);
    FSW_TRACE((stderr, "shape destroy %u (valid %d chain %d) update %d: %s\n", id.index1, valid, chain_seg, update,
               ga2d_result_string(r)));
    if (b->alloc.failures != gd.failures) s->pending_oom = 1; /* an end event that found no room */
    if (r == GA2D_ERR_MASS_OVERFLOW) FUZZ_CHECK(valid && !chain_seg && update && fsw_overflow_plausible(s, body));
    else FUZZ_CHECK(r == (!valid ? GA2D_ERR_STALE_ID : chain_seg ? GA2D_ERR_INVALID_ARGUMENT : GA2D_OK));
    fsw_guard_end(s, &gd, r);
    if (r != GA2D_OK) return;
    FUZZ_CHECK(!ga2d_shape_is_valid(w, id) && ga2d_body_id_is_null(ga2d_shape_body(w, id)));
    if (update && ga2d_body_get_type(w, body) == GA2D_BODY_DYNAMIC) {
        ga2d_mass after = ga2d_body_mass_data(w, body);
        FUZZ_CHECK(fz_finite((double)after.mass) && after.mass > 0 && fz_finite((double)after.inertia) && fz_finite_vec(after.center));
    }
    FUZZ_CHECK(ga2d_shape_get_type(w, id) == GA2D_SHAPE_TYPE_COUNT);
    FUZZ_CHECK(ga2d_body_get_shapes(w, body, NULL, 0) == n - 1);
    if (!update) {
        /* the body keeps its mass until the next change */
        s->mass_set = 1;
        ga2d_mass after = ga2d_body_mass_data(w, body);
        FUZZ_CHECK(memcmp(&after, &before, sizeof after) == 0);
    }
}

/* Friction, restitution or filter, on any shape id. */
static void fsw_shape_set(fsw_state *s)
{
    fw_state *b = &s->base;
    ga2d_world *w = b->w;
    ga2d_shape_id id = fsw_shape_id(s);
    int what = fz_pick(&b->rd, 3), valid = ga2d_shape_is_valid(w, id), wild = fz_u8(&b->rd) < 48;
    ga2d_real x = wild ? fz_real(&b->rd, 1) : fz_narrow((double)fz_u8(&b->rd) / 128);
    ga2d_result r, want;
    ga2d_filter f;
    fsw_guard gd;
    f.category_bits = fz_u32(&b->rd);
    f.mask_bits = fz_u8(&b->rd) < 128 ? 0xFFFFFFFFu : fz_u32(&b->rd);
    f.group_index = (int32_t)(int8_t)fz_u8(&b->rd);
    fsw_guard_begin(s, &gd);
    if (what == 0) r = ga2d_shape_set_friction(w, id, x);
    else if (what == 1) r = ga2d_shape_set_restitution(w, id, x);
    else r = ga2d_shape_set_filter(w, id, f);
    want = !valid ? GA2D_ERR_STALE_ID
                  : what == 2 ? GA2D_OK : !fz_finite((double)x) ? GA2D_ERR_NOT_FINITE : x < 0 ? GA2D_ERR_INVALID_ARGUMENT : GA2D_OK;
    FSW_TRACE((stderr, "shape set %d on %u (%g): %s\n", what, id.index1, (double)x, ga2d_result_string(r)));
    FUZZ_CHECK(r == want);
    fsw_guard_end(s, &gd, r);
    if (r == GA2D_OK && what == 2) {
        ga2d_filter got = ga2d_shape_filter(w, id);
        FUZZ_CHECK(memcmp(&got, &f, sizeof f) == 0);
    }
}

/* ---------------------------------------------------------------- chains */
/* A chain's points: a path of steps 1/8 to 2 long in any direction; a
   valley row (V and W shapes, every join concave or convex by turns, at
   slopes from flat to steep); a star (a loop with concave corners, either
   winding); or points on a grid over the whole coordinate range, out to
   +-GA2D_MAX_COORDINATE (the open ends' made-up ghosts lie beyond it). */
static void fsw_chain_points(fsw_state *s, ga2d_vec *pts, int n, int loop)
{
    fz_reader *rd = &s->base.rd;
    unsigned kind = fz_u8(rd) % 8;
    int i;
    pts[0].x = fz_narrow((double)(int8_t)fz_u8(rd) / 16);
    pts[0].y = fz_narrow((double)(int8_t)fz_u8(rd) / 16);
    if (kind < 3) {
        for (i = 1; i < n; ++i) {
            double a = (double)fz_u8(rd) * (6.283185307179586 / 256), len = (double)(4 + fz_u8(rd) % 60) / 32;
            pts[i] = ga2d_vec_add(pts[i - 1], ga2d_vec_make(fz_narrow(len * cos(a)), fz_narrow(len * sin(a))));
        }
    } else if (kind < 5) {
        /* valleys: x steps on, y goes down and up by the slope */
        double slope = (double)(1 + fz_u8(rd) % 64) / 16, dx = (double)(4 + fz_u8(rd) % 60) / 16, dir = (kind & 1) ? -1 : 1;
        for (i = 1; i < n; ++i)
            pts[i] = ga2d_vec_add(pts[i - 1], ga2d_vec_make(fz_narrow(dir * dx), fz_narrow((i & 1 ? -1 : 1) * slope * dx)));
    } else if (kind >= 6 && !loop) {
        /* the grid: coordinates -M, -M/2, 0, M/2, M, from a corner (where
           an end's made-up ghost is likeliest out of range) */
        static const unsigned corner[4] = {0, 4, 20, 24};
        for (i = 0; i < n; ++i) {
            unsigned g = i == 0 ? corner[fz_u8(rd) & 3] : fz_u8(rd);
            pts[i] = ga2d_vec_make(fz_narrow((double)GA2D_MAX_COORDINATE * (double)((int)(g % 5) - 2) / 2),
                                   fz_narrow((double)GA2D_MAX_COORDINATE * (double)((int)(g / 5 % 5) - 2) / 2));
        }
    } else if (kind == 5) {
        /* a star round pts[0], either way round */
        double r1 = (double)(8 + fz_u8(rd) % 56) / 16, r2 = r1 * (double)(2 + fz_u8(rd) % 13) / 16, sense = (fz_u8(rd) & 1) ? -1 : 1;
        ga2d_vec c = pts[0];
        for (i = 0; i < n; ++i) {
            double a = sense * 6.283185307179586 * i / n, rr = (i & 1) ? r2 : r1;
            pts[i] = ga2d_vec_add(c, ga2d_vec_make(fz_narrow(rr * cos(a)), fz_narrow(rr * sin(a))));
        }
    } else {
        /* a loop on the grid's corners and middles, either way */
        static const int ring[8][2] = {{-2, -2}, {0, -2}, {2, -2}, {2, 0}, {2, 2}, {0, 2}, {-2, 2}, {-2, 0}};
        int start = fz_pick(rd, 8), sense = (fz_u8(rd) & 1) ? 7 : 1;
        for (i = 0; i < n; ++i) {
            const int *q = ring[(start + i * sense) % 8];
            pts[i] = ga2d_vec_make(fz_narrow((double)GA2D_MAX_COORDINATE * q[0] / 2), fz_narrow((double)GA2D_MAX_COORDINATE * q[1] / 2));
        }
    }
}

/* An open end's made-up ghost lies behind the end at a right angle:
   along the segment by no more than the rounding of the ghost (whose
   coordinates are within 5 M), in front of it not at all. */
static void fsw_check_end_ghost(ga2d_vec end, ga2d_vec ghost, ga2d_vec p1, ga2d_vec p2)
{
    double ex = (double)p2.x - (double)p1.x, ey = (double)p2.y - (double)p1.y;
    double gx = (double)ghost.x - (double)end.x, gy = (double)ghost.y - (double)end.y;
    double el = sqrt(ex * ex + ey * ey), gl = sqrt(gx * gx + gy * gy);
    FUZZ_CHECK(gl > 0 && fabs(gx * ex + gy * ey) <= 8 * FZ_EPS * (gl + 10 * (double)GA2D_MAX_COORDINATE) * el);
    FUZZ_CHECK(gx * -ey + gy * ex < 0);
}

static void fsw_chain_create(fsw_state *s)
{
    fw_state *b = &s->base;
    ga2d_world *w = b->w;
    fz_reader *rd = &b->rd;
    ga2d_body_id body = fw_id(b);
    ga2d_chain_def d = ga2d_default_chain_def();
    ga2d_vec pts[FSW_MAX_POINTS];
    ga2d_chain_id id;
    ga2d_shape_id segs[FSW_MAX_POINTS + 1];
    unsigned flags = fz_u8(rd);
    int n = 1 + fz_pick(rd, FSW_MAX_POINTS), loop = flags & 1, mutate = fz_pick(rd, 10), clean, i, k, valid, btype, edges;
    ga2d_result r;
    fsw_guard gd;
    valid = ga2d_body_is_valid(w, body);
    btype = (int)ga2d_body_get_type(w, body);
    fsw_chain_points(s, pts, n, loop);
    clean = mutate < 6;
    k = fz_pick(rd, n);
    switch (mutate) {
    case 6: if (k > 0) pts[k] = pts[k - 1]; break; /* repeated */
    case 7: if (k > 0) pts[k] = ga2d_vec_make(pts[k - 1].x + pts[k - 1].x * (ga2d_real)FZ_EPS, pts[k - 1].y); break;
    case 8: /* folded back on itself: allowed */
        if (k > 1) pts[k] = pts[k - 2];
        clean = 1;
        break;
    case 9: pts[k] = fw_vec(b, 4, 1); break; /* anything: NaN, huge */
    default: break;
    }
    if (n < (loop ? 3 : 2)) clean = 0;
    if (clean)
        for (i = 0; i < (loop ? n : n - 1); ++i)
            if (fabs((double)pts[i].x - (double)pts[(i + 1) % n].x) + fabs((double)pts[i].y - (double)pts[(i + 1) % n].y) < 0.01) clean = 0;
    d.points = pts;
    d.count = n;
    d.is_loop = loop;
    if (flags & 2) {
        int wild = (flags & 4) != 0;
        d.friction = wild ? fz_real(rd, 1) : fz_narrow((double)fz_u8(rd) / 128);
        d.restitution = wild ? fz_real(rd, 1) : fz_narrow((double)fz_u8(rd) / 256);
        if (wild) clean = 0;
    }
    if (flags & 8) d.filter.category_bits = (uint32_t)1 << (fz_u8(rd) & 31);
    d.user_data = (flags & 16) ? &s->base.tag : NULL;
    if (flags & 32) {
        /* by hand: zeros are defaults */
        ga2d_chain_def h;
        memset(&h, 0, sizeof h);
        h.points = pts;
        h.count = n;
        h.is_loop = loop;
        d = h;
    }
    if ((flags & 0xC0) == 0xC0) {
        d.points = NULL;
        clean = 0;
    }
    if (s->nchains == FSW_MAX_CHAINS) return;
    fsw_guard_begin(s, &gd);
    if (flags & 64) {
        id = ga2d_chain_create(w, body, &d);
        r = id.index1 == 0 ? GA2D_ERR_INVALID_ARGUMENT : GA2D_OK;
    } else {
        r = ga2d_chain_create_checked(w, body, &d, &id);
        FUZZ_CHECK((int)r >= 0 && r < GA2D_RESULT_COUNT);
        FUZZ_CHECK((r == GA2D_OK) == (id.index1 != 0));
        if (!valid && clean) FUZZ_CHECK(r == GA2D_ERR_STALE_ID);
        if (valid && btype == GA2D_BODY_DYNAMIC && clean) FUZZ_CHECK(r == GA2D_ERR_INVALID_ARGUMENT);
        FUZZ_CHECK(r != GA2D_ERR_LOCKED);
    }
    FSW_TRACE((stderr, "chain create on %u (valid %d type %d) n %d loop %d mutate %d: %s\n", body.index1, valid, btype, n, loop,
               mutate, ga2d_result_string(r)));
    if (!valid || btype == GA2D_BODY_DYNAMIC || n < (loop ? 3 : 2) || !d.points) FUZZ_CHECK(r != GA2D_OK);
    if (mutate == 6 && k > 0 && (loop || k < n)) FUZZ_CHECK(r != GA2D_OK);
    if (valid && btype != GA2D_BODY_DYNAMIC && clean && b->alloc.failures == gd.failures)
        FUZZ_CHECK(r == GA2D_OK || (r == GA2D_ERR_MASS_OVERFLOW && fsw_overflow_plausible(s, body)));
    if (r == GA2D_ERR_MASS_OVERFLOW) FUZZ_CHECK(fsw_overflow_plausible(s, body));
    fsw_guard_end(s, &gd, r);
    if (r != GA2D_OK) return;
    /* whatever a world accepted, its snapshot loads */
    if (fz_u8(rd) < 64) fsw_round_trip(s);
    edges = loop ? n : n - 1;
    FUZZ_CHECK(ga2d_chain_get_segments(w, id, segs, FSW_MAX_POINTS + 1) == edges);
    for (i = 0; i < edges; ++i) {
        ga2d_geometry g = ga2d_shape_geometry(w, segs[i]);
        const ga2d_chain_segment *c = &g.as.chain_segment;
        FUZZ_CHECK(ga2d_shape_get_type(w, segs[i]) == GA2D_SHAPE_CHAIN_SEGMENT);
        FUZZ_CHECK(ga2d_body_id_equal(ga2d_shape_body(w, segs[i]), body));
        /* through the points, the neighbours' far ends as ghosts */
        FUZZ_CHECK(memcmp(&c->segment.point1, &pts[i], sizeof pts[i]) == 0);
        FUZZ_CHECK(memcmp(&c->segment.point2, &pts[(i + 1) % n], sizeof pts[i]) == 0);
        if (loop || i > 0) FUZZ_CHECK(memcmp(&c->ghost1, &pts[(i + n - 1) % n], sizeof pts[i]) == 0);
        else fsw_check_end_ghost(c->segment.point1, c->ghost1, c->segment.point1, c->segment.point2);
        if (loop || i + 2 < n) FUZZ_CHECK(memcmp(&c->ghost2, &pts[(i + 2) % n], sizeof pts[i]) == 0);
        else fsw_check_end_ghost(c->segment.point2, c->ghost2, c->segment.point1, c->segment.point2);
    }
    {
        fsw_chain *c = NULL;
        for (i = 0; i < s->nchains; ++i)
            if (s->chains[i].id.index1 == id.index1 && s->chains[i].id.generation == id.generation) c = &s->chains[i];
        if (!c) c = &s->chains[s->nchains++];
        c->id = id;
        c->body = body;
        c->n = edges;
        memcpy(c->segments, segs, (size_t)edges * sizeof segs[0]);
    }
}

static void fsw_chain_destroy(fsw_state *s)
{
    fw_state *b = &s->base;
    ga2d_world *w = b->w;
    ga2d_chain_id id;
    const fsw_chain *c = NULL;
    int valid, i;
    ga2d_result r;
    fsw_guard gd;
    memset(&id, 0, sizeof id);
    if (s->nchains > 0 && fz_u8(&b->rd) < 224) {
        c = &s->chains[fz_pick(&b->rd, s->nchains)];
        id = c->id;
    } else {
        id.index1 = fz_u8(&b->rd) % 4;
        id.generation = fz_u8(&b->rd);
    }
    valid = ga2d_chain_get_segments(w, id, NULL, 0) > 0;
    fsw_guard_begin(s, &gd);
    r = ga2d_chain_destroy(w, id);
    FSW_TRACE((stderr, "chain destroy %u (valid %d): %s\n", id.index1, valid, ga2d_result_string(r)));
    if (b->alloc.failures != gd.failures) s->pending_oom = 1;
    if (r == GA2D_ERR_MASS_OVERFLOW) FUZZ_CHECK(valid && c && fsw_overflow_plausible(s, c->body));
    else FUZZ_CHECK(r == (valid ? GA2D_OK : GA2D_ERR_STALE_ID));
    fsw_guard_end(s, &gd, r);
    if (r != GA2D_OK) return;
    FUZZ_CHECK(ga2d_chain_get_segments(w, id, NULL, 0) == 0);
    for (i = 0; c && i < c->n; ++i) FUZZ_CHECK(!ga2d_shape_is_valid(w, c->segments[i]));
}

/* -------------------------------------------------------------- bodies */
/* A body with no shape: shapes come later. */
static void fsw_create_bare(fsw_state *s)
{
    fw_state *b = &s->base;
    ga2d_body_def d = ga2d_default_body_def();
    unsigned k = fz_u8(&b->rd);
    long failures = b->alloc.failures;
    ga2d_body_id id;
    d.type = k % 3 == 0 ? GA2D_BODY_STATIC : k % 3 == 1 ? GA2D_BODY_KINEMATIC : GA2D_BODY_DYNAMIC;
    d.position = fw_vec(b, 4, 0);
    if (k & 4) d.velocity = fw_vec(b, 2, 0);
    if (k & 8) d.rotor = ga2d_rotor_from_angle(fw_val(b, 4, 0));
    d.is_awake = (k & 16) ? 0 : 1;
    if (b->nids == FW_MAX_IDS) return;
    id = ga2d_body_create(b->w, &d);
    FSW_TRACE((stderr, "bare body type %d -> %u\n", (int)d.type, id.index1));
    FUZZ_CHECK(!ga2d_body_id_is_null(id) || b->alloc.failures != failures);
    if (ga2d_body_id_is_null(id)) return;
    FUZZ_CHECK(ga2d_body_get_shapes(b->w, id, NULL, 0) == 0);
    b->ids[b->nids++] = id;
}

/* After a rollback a new body may take an id the harness saw before (its
   slot's generation came back): one entry per id. */
static void fsw_dedupe_bodies(fsw_state *s)
{
    fw_state *b = &s->base;
    int i, j;
    for (i = 0; i < b->nids; ++i)
        for (j = i + 1; j < b->nids; ++j)
            if (ga2d_body_id_equal(b->ids[i], b->ids[j])) {
                b->ids[j--] = b->ids[--b->nids];
            }
}

/* After a rollback: what the lost future made is gone, and its ids will be
   handed out again to other shapes, chains and bodies; the harness forgets
   them (ids stale before the checkpoint go too). */
static void fsw_forget_stale(fsw_state *s)
{
    ga2d_world *w = s->base.w;
    int i;
    for (i = 0; i < s->nshapes; ++i)
        if (!ga2d_shape_is_valid(w, s->shapes[i].id)) s->shapes[i--] = s->shapes[--s->nshapes];
    for (i = 0; i < s->nchains; ++i)
        if (ga2d_chain_get_segments(w, s->chains[i].id, NULL, 0) == 0) s->chains[i--] = s->chains[--s->nchains];
    for (i = 0; i < s->base.nids; ++i)
        if (!ga2d_body_is_valid(w, s->base.ids[i])) s->base.ids[i--] = s->base.ids[--s->base.nids];
}

/* ------------------------------------------------------------ snapshots */
/* Another world like this one (its def; an allocator that never fails). */
static ga2d_world *fsw_twin(fsw_state *s, fz_alloc *a, fsw_cb *cb)
{
    ga2d_world_def d = s->def;
    ga2d_world *t;
    memset(a, 0, sizeof *a);
    memset(cb, 0, sizeof *cb);
    fz_alloc_attach(a, &d);
    d.pre_solve_context = cb;
    t = ga2d_world_create(&d);
    FUZZ_CHECK(t != NULL);
    if (!t) return NULL;
    FUZZ_CHECK(ga2d_world_set_force_callback(t, s->field_on ? fw_field : NULL, &s->base) == GA2D_OK);
    cb->w = t;
    cb->mode = s->cb.mode;
    return t;
}

/* Save, load into a twin, save again: the same bytes; then the same steps
   in both: the same results and the same bytes. */
static void fsw_replay(fsw_state *s)
{
    fw_state *b = &s->base;
    fsw_buf s1, s2;
    fz_alloc ta;
    fsw_cb tcb;
    ga2d_world *t;
    int steps = 1 + fz_pick(&b->rd, 3), i, same = 1;
    long failures = b->alloc.failures;
    memset(&s1, 0, sizeof s1);
    memset(&s2, 0, sizeof s2);
    if (s->base.work > FW_WORK_BUDGET / 2 || !fsw_save(b->w, &s1)) {
        free(s1.p);
        return;
    }
    t = fsw_twin(s, &ta, &tcb);
    if (t) {
        ga2d_result r = ga2d_world_snapshot_load(t, s1.p, s1.n);
        FSW_TRACE((stderr, "replay: load %s, %d steps\n", ga2d_result_string(r), steps));
        FUZZ_CHECK(r == GA2D_OK);
        FUZZ_CHECK(fsw_save(t, &s2) && fsw_same(&s1, &s2));
        for (i = 0; i < steps && r == GA2D_OK; ++i) {
            ga2d_real dt = (ga2d_real)(fz_u8(&b->rd) < 200 ? 1.0 / 60 : 1.0 / 240);
            ga2d_result r1, r2;
            /* a lost end event's report is the original's alone (the
               snapshot does not carry it); stepping clears the flag */
            int pending = s->pending_oom;
            if (!fsw_step_dt(s, dt, &r1)) {
                same = 0;
                break;
            }
            r2 = ga2d_world_step(t, dt);
            FSW_TRACE((stderr, "replay step: %s / %s\n", ga2d_result_string(r1), ga2d_result_string(r2)));
            if (b->alloc.failures != failures) same = 0;
            if (same) FUZZ_CHECK(r1 == r2 || (r1 == GA2D_ERR_OUT_OF_MEMORY && pending));
        }
        if (same && b->alloc.failures == failures && fsw_save(b->w, &s1)) FUZZ_CHECK(fsw_save(t, &s2) && fsw_same(&s1, &s2));
        ga2d_world_destroy(t);
        FUZZ_CHECK(ta.live_bytes == 0 && ta.live_blocks == 0);
    }
    free(s1.p);
    free(s2.p);
}

/* A checkpoint: saved here, or loaded back (the world then saves to the
   same bytes, and its sensors' pairs are what it holds). */
static void fsw_checkpoint(fsw_state *s)
{
    fw_state *b = &s->base;
    if (fz_u8(&b->rd) < 128 || s->ckpt.n == 0) {
        if (!fsw_save(b->w, &s->ckpt)) s->ckpt.n = 0;
        s->ckpt_substeps = b->substeps;
        s->ckpt_rk4 = b->rk4;
        s->ckpt_passes = b->passes;
        FSW_TRACE((stderr, "checkpoint saved: %zu bytes\n", s->ckpt.n));
    } else {
        fsw_guard gd;
        ga2d_result r;
        fsw_guard_begin(s, &gd);
        r = ga2d_world_snapshot_load(b->w, s->ckpt.p, s->ckpt.n);
        FSW_TRACE((stderr, "rollback: %s\n", ga2d_result_string(r)));
        /* the world's own snapshot loads, unless memory runs out */
        FUZZ_CHECK(r == GA2D_OK || r == GA2D_ERR_OUT_OF_MEMORY);
        fsw_guard_end(s, &gd, r);
        if (r == GA2D_OK) {
            fsw_buf again;
            memset(&again, 0, sizeof again);
            if (fsw_save(b->w, &again)) FUZZ_CHECK(fsw_same(&again, &s->ckpt));
            free(again.p);
            s->pending_oom = 0;
            b->substeps = s->ckpt_substeps;
            b->rk4 = s->ckpt_rk4;
            b->passes = s->ckpt_passes;
            fsw_forget_stale(s);
            fsw_forget_joints(s);
            fsw_resync(s);
        }
    }
}

/* A world's own snapshot loads into a fresh world of its def and saves to
   the same bytes. */
static void fsw_round_trip(fsw_state *s)
{
    fsw_buf s1, s2;
    fz_alloc ta;
    fsw_cb tcb;
    ga2d_world *t;
    memset(&s1, 0, sizeof s1);
    memset(&s2, 0, sizeof s2);
    if (fsw_save(s->base.w, &s1) && (t = fsw_twin(s, &ta, &tcb)) != NULL) {
        ga2d_result r = ga2d_world_snapshot_load(t, s1.p, s1.n);
        FSW_TRACE((stderr, "round trip: %zu bytes, load %s\n", s1.n, ga2d_result_string(r)));
        FUZZ_CHECK(r == GA2D_OK);
        if (r == GA2D_OK) FUZZ_CHECK(fsw_save(t, &s2) && fsw_same(&s1, &s2));
        ga2d_world_destroy(t);
        FUZZ_CHECK(ta.live_bytes == 0 && ta.live_blocks == 0);
    }
    free(s1.p);
    free(s2.p);
}

/* -------------------------------------------------------------- queries */
static void fsw_queries(fsw_state *s)
{
    fw_state *b = &s->base;
    ga2d_world *w = b->w;
    ga2d_shape_id list[FSW_SCRATCH];
    ga2d_contact_data cd[8];
    int i, j, n;
    fw_queries(b);
    {
        ga2d_sensor_events se = ga2d_world_sensor_events(w);
        FUZZ_CHECK(se.begin_count >= 0 && se.end_count >= 0);
    }
    for (i = 0; i < s->nshapes; ++i) {
        const fsw_shape *e = &s->shapes[i];
        if (ga2d_shape_is_valid(w, e->id)) {
            ga2d_aabb box = ga2d_shape_fat_aabb(w, e->id);
            FUZZ_CHECK(ga2d_body_is_valid(w, e->body) && ga2d_body_id_equal(ga2d_shape_body(w, e->id), e->body));
            FUZZ_CHECK((int)ga2d_shape_get_type(w, e->id) == e->type && (int)ga2d_shape_geometry(w, e->id).type == e->type);
            FUZZ_CHECK(fz_finite_vec(box.lower) && fz_finite_vec(box.upper) && box.lower.x <= box.upper.x &&
                       box.lower.y <= box.upper.y);
        } else {
            /* stale: the getters read zero, the setters refuse */
            FUZZ_CHECK(ga2d_body_id_is_null(ga2d_shape_body(w, e->id)) && ga2d_shape_get_type(w, e->id) == GA2D_SHAPE_TYPE_COUNT);
            FUZZ_CHECK(ga2d_shape_user_data(w, e->id) == NULL);
            FUZZ_CHECK(ga2d_shape_set_friction(w, e->id, 1) == GA2D_ERR_STALE_ID);
            FUZZ_CHECK(ga2d_shape_get_sensor_overlaps(w, e->id, list, FSW_SCRATCH) == 0);
        }
    }
    for (i = 0; i < b->nids; ++i) {
        n = ga2d_body_get_shapes(w, b->ids[i], list, FSW_SCRATCH);
        FUZZ_CHECK(n >= 0 && (n == 0 || ga2d_body_is_valid(w, b->ids[i])));
        for (j = 0; j < n && j < FSW_SCRATCH; ++j)
            FUZZ_CHECK(ga2d_shape_is_valid(w, list[j]) && ga2d_body_id_equal(ga2d_shape_body(w, list[j]), b->ids[i]));
    }
    for (i = 0; i < s->nchains; ++i) {
        const fsw_chain *c = &s->chains[i];
        n = ga2d_chain_get_segments(w, c->id, list, FSW_SCRATCH);
        FUZZ_CHECK(n == 0 || (n == c->n && ga2d_body_is_valid(w, c->body)));
        for (j = 0; j < n; ++j) FUZZ_CHECK(ga2d_shape_id_equal(list[j], c->segments[j]));
    }
    fsw_check_joints(s, 0);
    n = ga2d_world_get_contacts(w, cd, 8);
    for (i = 0; i < n && i < 8; ++i) {
        FUZZ_CHECK(ga2d_body_id_equal(ga2d_shape_body(w, cd[i].shape_a), cd[i].body_a));
        FUZZ_CHECK(ga2d_body_id_equal(ga2d_shape_body(w, cd[i].shape_b), cd[i].body_b));
        FUZZ_CHECK(cd[i].shape_a.index1 < cd[i].shape_b.index1);
    }
}

/* --------------------------------------------------------------- joints */
/* The joint table: every joint the harness made (live or not), what it
   was made with, and, for a revolute joint, its limits while the harness
   knows them (a rollback forgets them). */
static int fsw_joint_find(const fsw_state *s, ga2d_joint_id id)
{
    int i;
    for (i = 0; i < s->njoints; ++i)
        if (ga2d_joint_id_equal(s->joints[i].id, id)) return i;
    return -1;
}

static void fsw_joint_remember(fsw_state *s, const fsw_joint *e)
{
    int i = fsw_joint_find(s, e->id);
    if (i >= 0) s->joints[i] = *e; /* an id a rollback handed out again */
    else if (s->njoints < FSW_MAX_JOINTS) s->joints[s->njoints++] = *e;
    else s->joints_lost = 1;
}

/* The joint an operation acts on: a tracked one (live or not), the null
   id, a forged one, or a tracked one with its generation off by one. */
static ga2d_joint_id fsw_joint_id(fsw_state *s)
{
    unsigned k = fz_u8(&s->base.rd);
    ga2d_joint_id id = ga2d_joint_id_null();
    if (s->njoints > 0 && k < 208) return s->joints[k % (unsigned)s->njoints].id;
    if (s->njoints > 0 && k < 224) {
        id = s->joints[k % (unsigned)s->njoints].id;
        id.generation += (k & 1) ? 1u : 0xFFFFFFFFu;
    } else if (k >= 240) {
        id.index1 = (k & 1) ? 0xFFFFFFFFu : (uint32_t)(k - 239);
        id.generation = (uint32_t)fz_u8(&s->base.rd);
    }
    return id;
}

/* A joint number: ordinary (k/16 x scale, made non-negative when asked),
   or (wild) anything: NaN, infinities, huge, negative. */
static ga2d_real fsw_jreal(fsw_state *s, double scale, int nonneg, int wild)
{
    if (wild) return fz_real(&s->base.rd, scale);
    return nonneg ? fz_narrow((double)fz_u8(&s->base.rd) * scale / 256) : fz_narrow((double)(int8_t)fz_u8(&s->base.rd) * scale / 16);
}

static int fsw_beyond(double x) { return fz_finite(x) && fabs(x) > (double)(ga2d_real)GA2D_MAX_COORDINATE; }
static int fsw_vec_beyond(ga2d_vec v) { return fsw_beyond((double)v.x) || fsw_beyond((double)v.y); }

/* What a call may answer: a set of results (bit r), OK only when nothing
   in it is wrong. */
#define FSW_BIT(r) (1u << (unsigned)(r))
static unsigned fsw_allowed(unsigned errors) { return errors ? errors : FSW_BIT(GA2D_OK); }

/* Is there a pair (touching or not) between the bodies a and b? */
static int fsw_pair_between(fsw_state *s, ga2d_body_id a, ga2d_body_id b)
{
    ga2d_world *w = s->base.w;
    int n = ga2d_world_get_pairs(w, NULL, 0), i, found = 0;
    ga2d_contact_data *c;
    if (n <= 0) return 0;
    c = (ga2d_contact_data *)malloc((size_t)n * sizeof *c);
    if (!c) return 0;
    FUZZ_CHECK(ga2d_world_get_pairs(w, c, n) == n);
    for (i = 0; i < n; ++i)
        if ((ga2d_body_id_equal(c[i].body_a, a) && ga2d_body_id_equal(c[i].body_b, b)) ||
            (ga2d_body_id_equal(c[i].body_a, b) && ga2d_body_id_equal(c[i].body_b, a)))
            found = 1;
    free(c);
    return found;
}

/* A dynamic body a joint call woke is awake (a sleeping one's island with
   it). */
static void fsw_check_woken(fsw_state *s, ga2d_body_id a, ga2d_body_id b)
{
    ga2d_world *w = s->base.w;
    if (ga2d_body_get_type(w, a) == GA2D_BODY_DYNAMIC) FUZZ_CHECK(ga2d_body_is_awake(w, a));
    if (ga2d_body_get_type(w, b) == GA2D_BODY_DYNAMIC) FUZZ_CHECK(ga2d_body_is_awake(w, b));
}

/* Every tracked joint against the world: a live one reads back what it
   was made with, its bodies live, finite readings, the island and pair
   rules; a stale one reads zero; the counters count them. */
static void fsw_check_joints(fsw_state *s, int after_step)
{
    ga2d_world *w = s->base.w;
    ga2d_world_counters c = ga2d_world_get_counters(w);
    int i, j, live = 0;
    /* joints_solved is the last step's: a joint destroyed since counts
       there and not in joint_count */
    FUZZ_CHECK(c.joint_count >= 0 && c.joints_solved >= 0);
    if (after_step) FUZZ_CHECK(c.joints_solved <= c.joint_count);
    if (s->njoints == 0 && !s->joints_lost) {
        FUZZ_CHECK(c.joint_count == 0 && (c.joints_solved == 0 || !after_step));
        return;
    }
    for (i = 0; i < s->njoints; ++i) {
        const fsw_joint *e = &s->joints[i];
        ga2d_joint_id id = e->id;
        ga2d_vec f = ga2d_joint_reaction_force(w, id);
        ga2d_real t = ga2d_joint_reaction_torque(w, id);
        int valid = ga2d_joint_is_valid(w, id), type = (int)ga2d_joint_get_type(w, id);
        ga2d_real angle = ga2d_revolute_joint_angle(w, id), speed = ga2d_revolute_joint_speed(w, id);
        ga2d_real torque = ga2d_revolute_joint_motor_torque(w, id), len = ga2d_distance_joint_current_length(w, id);
        for (j = 0; j < i; ++j)
            if (ga2d_joint_id_equal(s->joints[j].id, id)) break;
        FUZZ_CHECK(j == i); /* one entry an id */
        if (!valid) {
            FUZZ_CHECK(type == GA2D_JOINT_TYPE_COUNT && ga2d_body_id_is_null(ga2d_joint_body_a(w, id)) &&
                       ga2d_body_id_is_null(ga2d_joint_body_b(w, id)));
            FUZZ_CHECK(ga2d_joint_user_data(w, id) == NULL && ga2d_joint_collide_connected(w, id) == 0);
            FUZZ_CHECK(f.x == 0 && f.y == 0 && t == 0 && angle == 0 && speed == 0 && torque == 0 && len == 0);
            continue;
        }
        ++live;
        FUZZ_CHECK(type == e->type);
        FUZZ_CHECK(ga2d_body_id_equal(ga2d_joint_body_a(w, id), e->a) && ga2d_body_id_equal(ga2d_joint_body_b(w, id), e->b));
        /* a joint lives only while both its bodies do */
        FUZZ_CHECK(ga2d_body_is_valid(w, e->a) && ga2d_body_is_valid(w, e->b));
        FUZZ_CHECK(ga2d_joint_user_data(w, id) == e->user && ga2d_joint_collide_connected(w, id) == e->collide);
        FSW_TRACE((stderr, "joint %u reaction (%g %g) %g\n", id.index1, (double)f.x, (double)f.y, (double)t));
        /* the readings are impulse sums over the substep: after a
           containment, or on a body of a mass near the range (heavy
           shapes), the impulses are absurd but finite, saved and loaded
           as such, and their sum over h may overflow: not checked then */
        if (!s->contained && !s->heavy) FUZZ_CHECK(fz_finite_vec(f) && fz_finite((double)t));
        if (type == GA2D_JOINT_DISTANCE) FUZZ_CHECK(t == 0 && fz_finite((double)len) && len >= 0);
        else FUZZ_CHECK(len == 0);
        if (type == GA2D_JOINT_REVOLUTE) {
            /* within (-pi, pi], the wrap's rounding aside */
            FUZZ_CHECK(fz_finite((double)angle) && fabs((double)angle) <= 3.14159265358979 * (1 + 8 * FZ_EPS));
            if (!s->contained && !s->heavy) FUZZ_CHECK(fz_finite((double)torque)); /* an impulse over h, as above */
        } else {
            FUZZ_CHECK(angle == 0 && speed == 0 && torque == 0);
        }
        /* joined bodies are one island: both dynamic, both awake or both
           asleep */
        if (ga2d_body_get_type(w, e->a) == GA2D_BODY_DYNAMIC && ga2d_body_get_type(w, e->b) == GA2D_BODY_DYNAMIC)
            FUZZ_CHECK(ga2d_body_is_awake(w, e->a) == ga2d_body_is_awake(w, e->b));
        /* collide_connected 0: their shapes make no pair */
        if (!e->collide) FUZZ_CHECK(!fsw_pair_between(s, e->a, e->b));
    }
    if (!s->joints_lost) FUZZ_CHECK(c.joint_count == live);
}

/* A joint of any kind, on two bodies from the table (the same one, stale,
   null or forged at times), its numbers ordinary or hostile (NaN, inf,
   huge, negative, lower above upper, length 0); through the checked or
   the plain maker, with a NULL def or out at times.  Checked: the answer
   is one of the errors the def has (OK when it has none and no
   allocation failed), a refused call changes no byte of the world, a made
   joint reads back, its dynamic bodies wake, and (collide_connected 0)
   their pairs end. */
static void fsw_joint_create(fsw_state *s, const ga2d_body_id *on_bodies)
{
    fw_state *b = &s->base;
    ga2d_world *w = b->w;
    fz_reader *rd = &b->rd;
    unsigned flags = fz_u8(rd), kind = fz_u8(rd) % 4, wildness = fz_u8(rd);
    ga2d_body_id ba = on_bodies ? on_bodies[0] : fw_id(b), bb = on_bodies ? on_bodies[1] : (flags & 7) == 0 ? ba : fw_id(b);
    ga2d_vec la, lb;
    int va = ga2d_body_is_valid(w, ba), vb = ga2d_body_is_valid(w, bb), collide = (flags >> 3) & 1, by_hand = (flags & 0x30) == 0x30;
    int plain = (flags >> 6) == 3, null_arg = (flags >> 6) == 2 && (wildness & 15) == 0, count0, type = 0;
    unsigned errs = 0;
    void *user = (flags & 0x40) ? &b->tag : NULL;
    ga2d_joint_id id;
    ga2d_result r = GA2D_OK;
    fsw_guard gd;
    fsw_joint made;
    /* half the defs clean; the rest with each field wild at odds
       (wildness % 8) / 8 */
    int odds = wildness < 128 ? 0 : (int)(wildness % 8);
#define FSW_WILD() (fz_u8(rd) % 8 < (unsigned)odds)
    la = FSW_WILD() ? fw_vec(b, 2, 1) : fsw_vec(s, 0);
    lb = FSW_WILD() ? fw_vec(b, 2, 1) : fsw_vec(s, 0);
    if (!fz_finite_vec(la) || !fz_finite_vec(lb)) errs |= FSW_BIT(GA2D_ERR_NOT_FINITE);
    else if (fsw_vec_beyond(la) || fsw_vec_beyond(lb)) errs |= FSW_BIT(GA2D_ERR_TOO_LARGE);
    if (!va || !vb) errs |= FSW_BIT(GA2D_ERR_STALE_ID);
    else if (ga2d_body_id_equal(ba, bb) ||
             (ga2d_body_get_type(w, ba) != GA2D_BODY_DYNAMIC && ga2d_body_get_type(w, bb) != GA2D_BODY_DYNAMIC))
        errs |= FSW_BIT(GA2D_ERR_INVALID_ARGUMENT);
    if (s->njoints == FSW_MAX_JOINTS) return;
    count0 = ga2d_world_get_counters(w).joint_count;
    memset(&made, 0, sizeof made);
    fsw_guard_begin(s, &gd);
    id = ga2d_joint_id_null();
    switch (kind) {
    case 0: {
        ga2d_revolute_joint_def d = ga2d_default_revolute_joint_def();
        unsigned on = fz_u8(rd);
        type = GA2D_JOINT_REVOLUTE;
        if (by_hand) memset(&d, 0, sizeof d);
        d.body_a = ba, d.body_b = bb, d.local_anchor_a = la, d.local_anchor_b = lb, d.collide_connected = collide, d.user_data = user;
        d.enable_limit = on & 1, d.enable_motor = (on >> 1) & 1, d.enable_spring = (on >> 2) & 1;
        if (on & 8) d.reference_angle = fsw_jreal(s, 4, 0, FSW_WILD());
        if (on & 16) {
            d.lower_angle = fsw_jreal(s, 4, 0, FSW_WILD());
            d.upper_angle = fsw_jreal(s, 4, 0, FSW_WILD());
        }
        if (on & 32) {
            d.motor_speed = fsw_jreal(s, 8, 0, FSW_WILD());
            d.max_motor_torque = fsw_jreal(s, 100, 1, FSW_WILD());
        }
        if (on & 64) {
            d.hertz = fsw_jreal(s, 30, 1, FSW_WILD());
            d.damping_ratio = fsw_jreal(s, 4, 1, FSW_WILD());
        }
        if (!fz_finite((double)d.reference_angle) || !fz_finite((double)d.lower_angle) || !fz_finite((double)d.upper_angle) ||
            !fz_finite((double)d.motor_speed) || !fz_finite((double)d.max_motor_torque) || !fz_finite((double)d.hertz) ||
            !fz_finite((double)d.damping_ratio))
            errs |= FSW_BIT(GA2D_ERR_NOT_FINITE);
        if (d.max_motor_torque < 0 || d.hertz < 0 || d.damping_ratio < 0 || (d.enable_limit && d.lower_angle > d.upper_angle))
            errs |= FSW_BIT(GA2D_ERR_INVALID_ARGUMENT);
        FSW_TRACE((stderr, "revolute on %u %u limit %d [%g %g] motor %d %g %g spring %d %g %g ref %g\n", ba.index1, bb.index1,
                   d.enable_limit, (double)d.lower_angle, (double)d.upper_angle, d.enable_motor, (double)d.motor_speed,
                   (double)d.max_motor_torque, d.enable_spring, (double)d.hertz, (double)d.damping_ratio, (double)d.reference_angle));
        if (plain) id = ga2d_revolute_joint_create(w, &d);
        else r = ga2d_revolute_joint_create_checked(w, null_arg && (wildness & 16) ? NULL : &d, null_arg ? NULL : &id);
        made.limits_known = 1;
        made.lower = d.lower_angle;
        made.upper = d.upper_angle;
        break;
    }
    case 1: {
        ga2d_distance_joint_def d = ga2d_default_distance_joint_def();
        unsigned on = fz_u8(rd);
        type = GA2D_JOINT_DISTANCE;
        if (by_hand) memset(&d, 0, sizeof d);
        d.body_a = ba, d.body_b = bb, d.local_anchor_a = la, d.local_anchor_b = lb, d.collide_connected = collide, d.user_data = user;
        d.enable_limit = on & 1, d.enable_motor = (on >> 1) & 1, d.enable_spring = (on >> 2) & 1;
        if (on & 8) d.length = (on & 128) ? 0 : fsw_jreal(s, 4, 1, FSW_WILD());
        if (on & 16) {
            d.min_length = fsw_jreal(s, 4, 1, FSW_WILD());
            d.max_length = fsw_jreal(s, 4, 1, FSW_WILD());
        }
        if (on & 32) {
            d.motor_speed = fsw_jreal(s, 8, 0, FSW_WILD());
            d.max_motor_force = fsw_jreal(s, 100, 1, FSW_WILD());
        }
        if (on & 64) {
            d.hertz = fsw_jreal(s, 30, 1, FSW_WILD());
            d.damping_ratio = fsw_jreal(s, 4, 1, FSW_WILD());
        }
        if (!fz_finite((double)d.length) || !fz_finite((double)d.min_length) || !fz_finite((double)d.max_length) ||
            !fz_finite((double)d.motor_speed) || !fz_finite((double)d.max_motor_force) || !fz_finite((double)d.hertz) ||
            !fz_finite((double)d.damping_ratio))
            errs |= FSW_BIT(GA2D_ERR_NOT_FINITE);
        if ((fz_finite((double)d.length) && !(d.length > 0)) || d.min_length < 0 || d.min_length > d.max_length || d.hertz < 0 ||
            d.damping_ratio < 0 || d.max_motor_force < 0)
            errs |= FSW_BIT(GA2D_ERR_INVALID_ARGUMENT);
        FSW_TRACE((stderr, "distance on %u %u length %g limit %d [%g %g] motor %d %g %g spring %d %g %g\n", ba.index1, bb.index1,
                   (double)d.length, d.enable_limit, (double)d.min_length, (double)d.max_length, d.enable_motor,
                   (double)d.motor_speed, (double)d.max_motor_force, d.enable_spring, (double)d.hertz, (double)d.damping_ratio));
        if (plain) id = ga2d_distance_joint_create(w, &d);
        else r = ga2d_distance_joint_create_checked(w, null_arg && (wildness & 16) ? NULL : &d, null_arg ? NULL : &id);
        break;
    }
    case 2: {
        ga2d_weld_joint_def d = ga2d_default_weld_joint_def();
        unsigned on = fz_u8(rd);
        type = GA2D_JOINT_WELD;
        if (by_hand) memset(&d, 0, sizeof d);
        d.body_a = ba, d.body_b = bb, d.local_anchor_a = la, d.local_anchor_b = lb, d.collide_connected = collide, d.user_data = user;
        if (on & 1) d.reference_angle = fsw_jreal(s, 4, 0, FSW_WILD());
        if (on & 2) {
            d.linear_hertz = fsw_jreal(s, 30, 1, FSW_WILD());
            d.linear_damping_ratio = fsw_jreal(s, 4, 1, FSW_WILD());
        }
        if (on & 4) {
            d.angular_hertz = fsw_jreal(s, 30, 1, FSW_WILD());
            d.angular_damping_ratio = fsw_jreal(s, 4, 1, FSW_WILD());
        }
        if (!fz_finite((double)d.reference_angle) || !fz_finite((double)d.linear_hertz) || !fz_finite((double)d.angular_hertz) ||
            !fz_finite((double)d.linear_damping_ratio) || !fz_finite((double)d.angular_damping_ratio))
            errs |= FSW_BIT(GA2D_ERR_NOT_FINITE);
        if (d.linear_hertz < 0 || d.angular_hertz < 0 || d.linear_damping_ratio < 0 || d.angular_damping_ratio < 0)
            errs |= FSW_BIT(GA2D_ERR_INVALID_ARGUMENT);
        FSW_TRACE((stderr, "weld on %u %u ref %g linear %g %g angular %g %g\n", ba.index1, bb.index1, (double)d.reference_angle,
                   (double)d.linear_hertz, (double)d.linear_damping_ratio, (double)d.angular_hertz, (double)d.angular_damping_ratio));
        if (plain) id = ga2d_weld_joint_create(w, &d);
        else r = ga2d_weld_joint_create_checked(w, null_arg && (wildness & 16) ? NULL : &d, null_arg ? NULL : &id);
        break;
    }
    default: {
        ga2d_motor_joint_def d = ga2d_default_motor_joint_def();
        unsigned on = fz_u8(rd);
        type = GA2D_JOINT_MOTOR;
        if (by_hand) memset(&d, 0, sizeof d);
        d.body_a = ba, d.body_b = bb, d.local_anchor_a = la, d.local_anchor_b = lb, d.collide_connected = collide, d.user_data = user;
        if (on & 1) d.linear_offset = FSW_WILD() ? fw_vec(b, 4, 1) : fsw_vec(s, 0);
        if (on & 2) d.angular_offset = fsw_jreal(s, 4, 0, FSW_WILD());
        if (on & 4) {
            d.max_force = fsw_jreal(s, 100, 1, FSW_WILD());
            d.max_torque = fsw_jreal(s, 100, 1, FSW_WILD());
        }
        if (on & 8) d.correction_factor = FSW_WILD() ? fz_real(rd, 1) : fz_narrow((double)fz_u8(rd) / 255);
        if (!fz_finite_vec(d.linear_offset) || !fz_finite((double)d.angular_offset) || !fz_finite((double)d.max_force) ||
            !fz_finite((double)d.max_torque) || !fz_finite((double)d.correction_factor))
            errs |= FSW_BIT(GA2D_ERR_NOT_FINITE);
        if (d.max_force < 0 || d.max_torque < 0 || d.correction_factor < 0 || d.correction_factor > 1)
            errs |= FSW_BIT(GA2D_ERR_INVALID_ARGUMENT);
        if (fsw_vec_beyond(d.linear_offset)) errs |= FSW_BIT(GA2D_ERR_TOO_LARGE);
        FSW_TRACE((stderr, "motor joint on %u %u offset (%g %g) %g max %g %g factor %g\n", ba.index1, bb.index1,
                   (double)d.linear_offset.x, (double)d.linear_offset.y, (double)d.angular_offset, (double)d.max_force,
                   (double)d.max_torque, (double)d.correction_factor));
        if (plain) id = ga2d_motor_joint_create(w, &d);
        else r = ga2d_motor_joint_create_checked(w, null_arg && (wildness & 16) ? NULL : &d, null_arg ? NULL : &id);
        break;
    }
    }
#undef FSW_WILD
    if (plain) r = ga2d_joint_id_is_null(id) ? GA2D_ERR_INVALID_ARGUMENT : GA2D_OK;
    FSW_TRACE((stderr, "joint create kind %u (plain %d null %d) errors %x: %s -> %u\n", kind, plain, null_arg, errs,
               ga2d_result_string(r), id.index1));
    FUZZ_CHECK((int)r >= 0 && r < GA2D_RESULT_COUNT);
    FUZZ_CHECK((r == GA2D_OK) == !ga2d_joint_id_is_null(id));
    if (null_arg) FUZZ_CHECK(r == GA2D_ERR_INVALID_ARGUMENT);
    else if (plain) FUZZ_CHECK((r == GA2D_OK) == (errs == 0 && b->alloc.failures == gd.failures));
    else if (b->alloc.failures != gd.failures && r == GA2D_ERR_OUT_OF_MEMORY) FUZZ_CHECK(errs == 0);
    else FUZZ_CHECK(fsw_allowed(errs) & FSW_BIT(r));
    fsw_guard_end(s, &gd, r);
    if (r != GA2D_OK) {
        FUZZ_CHECK(ga2d_world_get_counters(w).joint_count == count0);
        return;
    }
    {
        fsw_joint e = made;
        e.id = id;
        e.a = ba;
        e.b = bb;
        e.type = type;
        e.collide = collide;
        e.user = user;
        fsw_joint_remember(s, &e);
    }
    FUZZ_CHECK(ga2d_joint_is_valid(w, id) && (int)ga2d_joint_get_type(w, id) == type);
    FUZZ_CHECK(ga2d_world_get_counters(w).joint_count == count0 + 1);
    fsw_check_woken(s, ba, bb);
    if (!collide) FUZZ_CHECK(!fsw_pair_between(s, ba, bb));
    fsw_check_joints(s, 0);
    /* whatever a world accepted, its snapshot loads */
    if (fz_u8(rd) < 64) fsw_round_trip(s);
}

/* Destroys a joint (a tracked one, stale, null or forged): OK for a live
   one (it goes stale, its bodies wake, the count drops), else STALE_ID
   and nothing changes. */
static void fsw_joint_destroy(fsw_state *s)
{
    ga2d_world *w = s->base.w;
    ga2d_joint_id id = fsw_joint_id(s);
    int valid = ga2d_joint_is_valid(w, id), count0 = ga2d_world_get_counters(w).joint_count;
    ga2d_body_id a = ga2d_joint_body_a(w, id), b = ga2d_joint_body_b(w, id);
    ga2d_result r;
    fsw_guard gd;
    fsw_guard_begin(s, &gd);
    r = ga2d_joint_destroy(w, id);
    FSW_TRACE((stderr, "joint destroy %u/%u (valid %d): %s\n", id.index1, id.generation, valid, ga2d_result_string(r)));
    FUZZ_CHECK(r == (valid ? GA2D_OK : GA2D_ERR_STALE_ID));
    fsw_guard_end(s, &gd, r);
    FUZZ_CHECK(ga2d_world_get_counters(w).joint_count == count0 - (r == GA2D_OK));
    if (r != GA2D_OK) return;
    FUZZ_CHECK(!ga2d_joint_is_valid(w, id) && ga2d_joint_get_type(w, id) == GA2D_JOINT_TYPE_COUNT);
    FUZZ_CHECK(ga2d_joint_destroy(w, id) == GA2D_ERR_STALE_ID);
    fsw_check_woken(s, a, b);
}

/* Every setter, on any joint id: mostly one of the joint's own kind, with
   a value ordinary or hostile.  The answer: STALE_ID for a stale id,
   INVALID_ARGUMENT for another kind, else one of the value's errors (OK
   when it has none); a refused call changes no byte of the world, an
   accepted one wakes the bodies. */
#define FSW_NSETTERS 21
static void fsw_joint_set(fsw_state *s)
{
    static const int kind_of[FSW_NSETTERS] = {GA2D_JOINT_REVOLUTE, GA2D_JOINT_REVOLUTE, GA2D_JOINT_REVOLUTE, GA2D_JOINT_REVOLUTE,
                                              GA2D_JOINT_REVOLUTE, GA2D_JOINT_REVOLUTE, GA2D_JOINT_REVOLUTE, GA2D_JOINT_DISTANCE,
                                              GA2D_JOINT_DISTANCE, GA2D_JOINT_DISTANCE, GA2D_JOINT_DISTANCE, GA2D_JOINT_DISTANCE,
                                              GA2D_JOINT_DISTANCE, GA2D_JOINT_DISTANCE, GA2D_JOINT_DISTANCE, GA2D_JOINT_WELD,
                                              GA2D_JOINT_WELD,     GA2D_JOINT_MOTOR,    GA2D_JOINT_MOTOR,    GA2D_JOINT_MOTOR,
                                              GA2D_JOINT_MOTOR};
    static const int first[4][2] = {{7, 8}, {0, 7}, {15, 2}, {17, 4}}; /* by kind: distance, revolute, weld, motor */
    fw_state *bs = &s->base;
    ga2d_world *w = bs->w;
    fz_reader *rd = &bs->rd;
    ga2d_joint_id id = fsw_joint_id(s);
    int valid = ga2d_joint_is_valid(w, id), type = (int)ga2d_joint_get_type(w, id), k = fsw_joint_find(s, id);
    unsigned pick = fz_u8(rd), wildness = fz_u8(rd);
    int which, wild = wildness < 48, on = (int)(wildness & 3) - 1; /* enable: -1, 0, 1, 2 */
    ga2d_real x = 0, y = 0;
    ga2d_vec v = ga2d_vec_make(0, 0);
    unsigned errs = 0;
    ga2d_result r;
    fsw_guard gd;
    ga2d_body_id a = ga2d_joint_body_a(w, id), b = ga2d_joint_body_b(w, id);
    if (valid && pick < 192) {
        int slot = type == GA2D_JOINT_DISTANCE ? 0 : type == GA2D_JOINT_REVOLUTE ? 1 : type == GA2D_JOINT_WELD ? 2 : 3;
        which = first[slot][0] + (int)(fz_u8(rd) % (unsigned)first[slot][1]);
    } else {
        which = (int)(fz_u8(rd) % FSW_NSETTERS);
    }
    if (!valid) errs = FSW_BIT(GA2D_ERR_STALE_ID);
    else if (type != kind_of[which]) errs = FSW_BIT(GA2D_ERR_INVALID_ARGUMENT);
    fsw_guard_begin(s, &gd);
    switch (which) {
    case 0: r = ga2d_revolute_joint_enable_motor(w, id, on); break;
    case 1:
        x = fsw_jreal(s, 8, 0, wild);
        r = ga2d_revolute_joint_set_motor_speed(w, id, x);
        break;
    case 2:
        x = fsw_jreal(s, 100, 1, wild);
        r = ga2d_revolute_joint_set_max_motor_torque(w, id, x);
        break;
    case 3:
        if (!errs && on && k >= 0 && s->joints[k].limits_known && s->joints[k].lower > s->joints[k].upper)
            errs = FSW_BIT(GA2D_ERR_INVALID_ARGUMENT);
        else if (!errs && on && !(k >= 0 && s->joints[k].limits_known))
            errs = FSW_BIT(GA2D_OK) | FSW_BIT(GA2D_ERR_INVALID_ARGUMENT); /* the limits are not known here */
        r = ga2d_revolute_joint_enable_limit(w, id, on);
        break;
    case 4:
        x = fsw_jreal(s, 4, 0, wild);
        y = fsw_jreal(s, 4, 0, wild || (wildness & 4));
        r = ga2d_revolute_joint_set_limits(w, id, x, y);
        break;
    case 5: r = ga2d_revolute_joint_enable_spring(w, id, on); break;
    case 6: case 11: case 15: case 16:
        x = fsw_jreal(s, 30, 1, wild);
        y = fsw_jreal(s, 4, 1, wild);
        r = which == 6    ? ga2d_revolute_joint_set_spring(w, id, x, y)
            : which == 11 ? ga2d_distance_joint_set_spring(w, id, x, y)
            : which == 15 ? ga2d_weld_joint_set_linear_spring(w, id, x, y)
                          : ga2d_weld_joint_set_angular_spring(w, id, x, y);
        break;
    case 7:
        x = (wildness & 8) ? 0 : fsw_jreal(s, 4, 1, wild);
        r = ga2d_distance_joint_set_length(w, id, x);
        break;
    case 8: r = ga2d_distance_joint_enable_limit(w, id, on); break;
    case 9:
        x = fsw_jreal(s, 4, 1, wild);
        y = fsw_jreal(s, 4, 1, wild || (wildness & 4));
        r = ga2d_distance_joint_set_length_range(w, id, x, y);
        break;
    case 10: r = ga2d_distance_joint_enable_spring(w, id, on); break;
    case 12: r = ga2d_distance_joint_enable_motor(w, id, on); break;
    case 13:
        x = fsw_jreal(s, 8, 0, wild);
        r = ga2d_distance_joint_set_motor_speed(w, id, x);
        break;
    case 14: case 19: case 20:
        x = fsw_jreal(s, 100, 1, wild);
        r = which == 14 ? ga2d_distance_joint_set_max_motor_force(w, id, x)
            : which == 19 ? ga2d_motor_joint_set_max_force(w, id, x)
                          : ga2d_motor_joint_set_max_torque(w, id, x);
        break;
    case 17:
        v = wild ? fw_vec(bs, 4, 1) : fsw_vec(s, 0);
        r = ga2d_motor_joint_set_linear_offset(w, id, v);
        break;
    default:
        x = fsw_jreal(s, 4, 0, wild);
        r = ga2d_motor_joint_set_angular_offset(w, id, x);
        break;
    }
    if (!errs) {
        /* the value's own errors */
        int two = which == 4 || which == 6 || which == 9 || which == 11 || which == 15 || which == 16;
        if (!fz_finite((double)x) || (two && !fz_finite((double)y)) || !fz_finite_vec(v)) errs |= FSW_BIT(GA2D_ERR_NOT_FINITE);
        switch (which) {
        case 2: case 14: case 19: case 20: if (x < 0) errs |= FSW_BIT(GA2D_ERR_INVALID_ARGUMENT); break;
        case 4: if (x > y) errs |= FSW_BIT(GA2D_ERR_INVALID_ARGUMENT); break;
        case 6: case 11: case 15: case 16: if (x < 0 || y < 0) errs |= FSW_BIT(GA2D_ERR_INVALID_ARGUMENT); break;
        case 7: if (fz_finite((double)x) && !(x > 0)) errs |= FSW_BIT(GA2D_ERR_INVALID_ARGUMENT); break;
        case 9: if (x < 0 || x > y) errs |= FSW_BIT(GA2D_ERR_INVALID_ARGUMENT); break;
        case 17: if (fsw_vec_beyond(v)) errs |= FSW_BIT(GA2D_ERR_TOO_LARGE); break;
        default: break;
        }
    }
    FSW_TRACE((stderr, "joint set %d on %u (valid %d type %d) x %g y %g v (%g %g) on %d: %s (allowed %x)\n", which, id.index1, valid,
               type, (double)x, (double)y, (double)v.x, (double)v.y, on, ga2d_result_string(r), fsw_allowed(errs)));
    FUZZ_CHECK((int)r >= 0 && r < GA2D_RESULT_COUNT);
    FUZZ_CHECK(fsw_allowed(errs) & FSW_BIT(r));
    fsw_guard_end(s, &gd, r);
    if (r != GA2D_OK) return;
    FUZZ_CHECK(ga2d_joint_is_valid(w, id) && (int)ga2d_joint_get_type(w, id) == type);
    fsw_check_woken(s, a, b);
    if (which == 4 && k >= 0) {
        s->joints[k].limits_known = 1;
        s->joints[k].lower = x;
        s->joints[k].upper = y;
    }
    if (fz_u8(rd) < 16) fsw_round_trip(s);
}

/* A chain: 2 to 6 joints, each between a tracked body and the next in
   the table (ropes, bridges, ragdolls: islands of several bodies), each
   made as fsw_joint_create makes one. */
static void fsw_joint_chain(fsw_state *s)
{
    fw_state *b = &s->base;
    int n = 2 + fz_pick(&b->rd, 5), at = fz_u8(&b->rd), i;
    for (i = 0; i < n && b->nids > 1; ++i) {
        ga2d_body_id pair[2];
        pair[0] = b->ids[(at + i) % b->nids];
        pair[1] = b->ids[(at + i + 1) % b->nids];
        fsw_joint_create(s, pair);
    }
}

/* One joint operation: make (most often), a chain, set, destroy, or
   check. */
static void fsw_joint_op(fsw_state *s)
{
    unsigned k = fz_u8(&s->base.rd) % 8;
    if (k < 3) fsw_joint_create(s, NULL);
    else if (k == 3) fsw_joint_chain(s);
    else if (k < 6) fsw_joint_set(s);
    else if (k == 6) fsw_joint_destroy(s);
    else fsw_check_joints(s, 0);
}

/* After a rollback: the joints the lost future made are gone (their ids
   will come again), and what the harness knew of limits is old. */
static void fsw_forget_joints(fsw_state *s)
{
    int i;
    for (i = 0; i < s->njoints; ++i) {
        s->joints[i].limits_known = 0;
        if (!ga2d_joint_is_valid(s->base.w, s->joints[i].id)) s->joints[i--] = s->joints[--s->njoints];
    }
}

/* ------------------------------------------------ world queries (issue 25) */
/* Queries through the broadphase: rays (closest, and every hit with a
   callback that sees all, ignores, clips, stops, or answers NaN, past 1
   or a half by the shape's id), overlaps (box, point, shape), shape
   casts, the body list, the continuous switch, bullets and fast bodies.
   What is checked (the header's promises): a refusal is the documented
   one (NOT_FINITE for a value not finite, the ray's end included;
   INVALID_ARGUMENT for a zero translation, a NULL callback or world, a
   box upside down); every shape a callback gets is live, seen by the
   filter, no sensor, and given once; a hit's fraction lies in [0, the
   ray's clip so far], its point and normal are finite, its normal unit
   (a shape cast's may be 0 at fraction 0: cores overlapping), a ray
   hit's point on the ray at its fraction; a callback is never called
   after it said stop; inside a callback every change (step, makers,
   destroys, setters, the continuous switch, bullets) and every other
   query is LOCKED; the world's snapshot is the same bytes after a query
   as before; counters: query_shapes <= query_nodes and <= shape_count.
   Against an O(n) scan of every shape (ga2d_ray_cast_shape on each):
   the all-hits ray with a callback that sees all gets exactly the shapes
   that scan hits, with the same fractions, and the closest ray the
   least of them; a box overlap gets every shape whose own box overlaps
   it and no other (within the rounding of the boxes); a point overlap
   only shapes within rounding of the point, never a segment, and every
   circle that surely holds it; a shape overlap only shapes within
   rounding of the proxy.  Tolerance: a point placed by a body's
   transform rounds by a few eps of the sizes involved; 64 eps S (S the
   1-norms of the ray, the body's position and the point) covers it with
   a margin, FZ_TINY * 4 an underflow. */
#define FSW_QMAX 256

static double fsw_n1(ga2d_vec v) { return fabs((double)v.x) + fabs((double)v.y); }

typedef struct fsw_q {
    fsw_state *s;
    ga2d_world *w;
    ga2d_vec origin, translation;
    ga2d_filter filter;
    int mode;   /* 0 see all, 1 ignore all, 2 clip to each hit, 3 stop at the first, 4 mixed by id */
    int meddle; /* try changes from inside */
    int shape_cast, stopped, calls;
    ga2d_real clip;
    ga2d_shape_id seen[FSW_QMAX];
    ga2d_real fraction[FSW_QMAX];
    int nseen, lost;
} fsw_q;

static int fsw_q_index(const fsw_q *q, ga2d_shape_id id)
{
    int i;
    for (i = 0; i < q->nseen; ++i)
        if (ga2d_shape_id_equal(q->seen[i], id)) return i;
    return -1;
}

static ga2d_real fsw_q_never(ga2d_shape_id shape, ga2d_vec p, ga2d_vec n, ga2d_real f, void *ctx)
{
    (void)shape;
    (void)p;
    (void)n;
    (void)f;
    (void)ctx;
    FUZZ_CHECK(0); /* a refused query calls nothing */
    return 0;
}

static int fsw_q_never_overlap(ga2d_shape_id shape, void *ctx)
{
    (void)shape;
    (void)ctx;
    FUZZ_CHECK(0);
    return 0;
}

/* Every change from inside a query's callback: LOCKED, and nothing
   changed (the snapshot after the query shows it). */
static void fsw_q_meddle(fsw_q *q, ga2d_shape_id shape)
{
    ga2d_world *w = q->w;
    ga2d_body_id body = ga2d_shape_body(w, shape);
    ga2d_body_def bd = ga2d_default_body_def();
    ga2d_shape_def sd = ga2d_default_shape_def();
    ga2d_circle c;
    ga2d_ray_result rr;
    ga2d_aabb box;
    ga2d_shape_proxy px;
    ga2d_vec o = ga2d_vec_make(0, 0), t = ga2d_vec_make(1, 0);
    c.center = o;
    c.radius = 1;
    box.lower = ga2d_vec_make(-1, -1);
    box.upper = ga2d_vec_make(1, 1);
    px = ga2d_make_proxy(&o, 1, 1);
    bd.type = GA2D_BODY_DYNAMIC;
    FUZZ_CHECK(ga2d_world_step(w, (ga2d_real)(1.0 / 60)) == GA2D_ERR_LOCKED);
    FUZZ_CHECK(ga2d_body_id_is_null(ga2d_body_create(w, &bd)));
    FUZZ_CHECK(ga2d_body_destroy(w, body) == GA2D_ERR_LOCKED);
    FUZZ_CHECK(ga2d_shape_id_is_null(ga2d_shape_create_circle(w, body, &sd, &c)));
    FUZZ_CHECK(ga2d_shape_destroy(w, shape, 1) == GA2D_ERR_LOCKED);
    FUZZ_CHECK(ga2d_shape_set_filter(w, shape, ga2d_default_filter()) == GA2D_ERR_LOCKED);
    FUZZ_CHECK(ga2d_body_set_transform(w, body, o, ga2d_rotor_identity()) == GA2D_ERR_LOCKED);
    FUZZ_CHECK(ga2d_body_set_velocity(w, body, t) == GA2D_ERR_LOCKED);
    FUZZ_CHECK(ga2d_body_set_bullet(w, body, 1) == GA2D_ERR_LOCKED);
    FUZZ_CHECK(ga2d_world_enable_continuous(w, 0) == GA2D_ERR_LOCKED);
    FUZZ_CHECK(ga2d_world_set_gravity(w, t) == GA2D_ERR_LOCKED);
    FUZZ_CHECK(ga2d_world_compact(w) == GA2D_ERR_LOCKED);
    FUZZ_CHECK(ga2d_world_cast_ray_closest_checked(w, o, t, q->filter, &rr) == GA2D_ERR_LOCKED);
    FUZZ_CHECK(!ga2d_world_cast_ray_closest(w, o, t, q->filter).hit);
    FUZZ_CHECK(ga2d_world_cast_ray(w, o, t, q->filter, fsw_q_never, NULL) == GA2D_ERR_LOCKED);
    FUZZ_CHECK(ga2d_world_overlap_aabb(w, box, q->filter, fsw_q_never_overlap, NULL) == GA2D_ERR_LOCKED);
    FUZZ_CHECK(ga2d_world_overlap_point(w, o, q->filter, fsw_q_never_overlap, NULL) == GA2D_ERR_LOCKED);
    FUZZ_CHECK(ga2d_world_overlap_shape(w, &px, ga2d_transform_identity(), q->filter, fsw_q_never_overlap, NULL) ==
               GA2D_ERR_LOCKED);
    FUZZ_CHECK(ga2d_world_cast_shape(w, &px, ga2d_transform_identity(), t, q->filter, fsw_q_never, NULL) == GA2D_ERR_LOCKED);
    /* reading is allowed */
    FUZZ_CHECK(ga2d_world_get_bodies(w, NULL, 0) == ga2d_world_get_counters(w).body_count);
    FUZZ_CHECK(ga2d_shape_is_valid(w, shape));
}

/* What every callback checks of the shape it gets. */
static void fsw_q_shape(fsw_q *q, ga2d_shape_id shape)
{
    ga2d_world *w = q->w;
    FUZZ_CHECK(!q->stopped);
    FUZZ_CHECK(ga2d_shape_is_valid(w, shape));
    FUZZ_CHECK(!fsw_lookup(q->s, shape).sensor);
    FUZZ_CHECK(ga2d_should_collide(q->filter, ga2d_shape_filter(w, shape)));
    FUZZ_CHECK(fsw_q_index(q, shape) < 0); /* once */
    ++q->calls;
    if (q->meddle && q->calls <= 2) fsw_q_meddle(q, shape);
}

static void fsw_q_remember(fsw_q *q, ga2d_shape_id shape, ga2d_real f)
{
    if (q->nseen == FSW_QMAX) {
        q->lost = 1;
        return;
    }
    q->seen[q->nseen] = shape;
    q->fraction[q->nseen++] = f;
}

static double fsw_q_tol(double S) { return 64 * FZ_EPS * S + 4 * FZ_TINY; }

static ga2d_real fsw_q_cast(ga2d_shape_id shape, ga2d_vec p, ga2d_vec n, ga2d_real f, void *ctx)
{
    static const double mixed[6] = {(double)NAN, 2, 0.5, -1, -2, 1}; /* -2: the hit's own fraction */
    fsw_q *q = (fsw_q *)ctx;
    double l2 = (double)n.x * (double)n.x + (double)n.y * (double)n.y;
    ga2d_real go_on;
    fsw_q_shape(q, shape);
    FUZZ_CHECK(f >= 0 && f <= q->clip);
    FUZZ_CHECK(fz_finite_vec(p) && fz_finite_vec(n));
    /* |n|^2 of a normalized vector, or a rotated unit normal: a few eps */
    FUZZ_CHECK(fabs(l2 - 1) <= 16 * FZ_EPS || (q->shape_cast && f == 0 && l2 == 0));
    if (!q->shape_cast) {
        /* on the ray at its fraction: the hit is o' + f' t' in the shape's
           frame, placed back by the body's transform */
        double S = fsw_n1(q->origin) + fsw_n1(q->translation) + fsw_n1(p) + fsw_n1(ga2d_body_position(q->w, ga2d_shape_body(q->w, shape)));
        double tol = fsw_q_tol(S);
        FUZZ_CHECK(fabs((double)q->origin.x + (double)f * (double)q->translation.x - (double)p.x) <= tol);
        FUZZ_CHECK(fabs((double)q->origin.y + (double)f * (double)q->translation.y - (double)p.y) <= tol);
    }
    fsw_q_remember(q, shape, f);
    switch (q->mode) {
    case 0: go_on = 1; break;
    case 1: go_on = -1; break;
    case 2: go_on = f; break;
    case 3: go_on = 0; break;
    default: {
        double m = mixed[shape.index1 % 6u];
        go_on = m == -2 ? f : fz_narrow(m);
        break;
    }
    }
    /* the protocol, as the header states it */
    if (go_on == 0) q->stopped = 1;
    else if (go_on > 0 && go_on < q->clip) q->clip = go_on;
    return go_on;
}

static int fsw_q_overlap(ga2d_shape_id shape, void *ctx)
{
    fsw_q *q = (fsw_q *)ctx;
    fsw_q_shape(q, shape);
    fsw_q_remember(q, shape, 0);
    if (q->mode == 3) {
        q->stopped = 1;
        return 0;
    }
    return 1;
}

/* Every live shape in the world (bodies listed, then their shapes). */
static int fsw_q_all_shapes(ga2d_world *w, ga2d_shape_id *out, int cap)
{
    ga2d_body_id bodies[FSW_QMAX];
    int nb = ga2d_world_get_bodies(w, bodies, FSW_QMAX), i, n = 0;
    if (nb > FSW_QMAX) return -1;
    for (i = 0; i < nb; ++i) {
        int k = ga2d_body_get_shapes(w, bodies[i], out + n, cap - n);
        if (k > cap - n) return -1;
        n += k;
    }
    return n;
}

static int fsw_q_sees(const fsw_q *q, ga2d_shape_id id)
{
    return !fsw_lookup(q->s, id).sensor && ga2d_should_collide(q->filter, ga2d_shape_filter(q->w, id));
}

/* The query's frame: the snapshot before, a fresh callback state. */
static int fsw_q_any(ga2d_shape_id shape, void *ctx)
{
    (void)shape;
    (void)ctx;
    return 1;
}

static void fsw_q_begin(fsw_state *s, fsw_q *q, fsw_buf *before, int *saved)
{
    ga2d_aabb here;
    /* a query that surely runs first: a refused query leaves the counters
       as the last one that ran left them, which may have seen shapes
       destroyed since (fsw_q_end bounds them by the shapes now) */
    here.lower = here.upper = ga2d_vec_make(0, 0);
    (void)ga2d_world_overlap_aabb(s->base.w, here, ga2d_default_filter(), fsw_q_any, NULL);
    memset(before, 0, sizeof *before);
    *saved = fsw_save(s->base.w, before);
    q->s = s;
    q->w = s->base.w;
    q->clip = 1;
    q->stopped = q->calls = q->nseen = q->lost = 0;
}

/* After it: the same bytes, counters within the shape count. */
static void fsw_q_end(fsw_state *s, fsw_buf *before, int saved)
{
    ga2d_world_counters c = ga2d_world_get_counters(s->base.w);
    fsw_buf after;
    FUZZ_CHECK(c.query_shapes >= 0 && c.query_shapes <= c.shape_count && c.query_shapes <= c.query_nodes);
    memset(&after, 0, sizeof after);
    if (saved && fsw_save(s->base.w, &after)) FUZZ_CHECK(fsw_same(before, &after));
    free(after.p);
    free(before->p);
}


/* Whether a query must find a shape: always, but where the rounding of a
   query of size S (the tree's box tests round too) reaches a metre, only
   if the shape lies inside its broadphase box with room for it.  The
   step keeps every shape inside its tree box (a body carried out of its
   boxes during the step, by a joint, a contact, a spring or the field,
   gets them grown at the step's end), so between steps a query misses
   nothing. */
static int fsw_q_in_tree_box(ga2d_world *w, ga2d_shape_id id, double S)
{
    double S0, tol;
    ga2d_aabb own = fsw_q_shape_box(w, id, &S0), fat = ga2d_shape_fat_aabb(w, id);
    tol = fsw_q_tol(S + S0);
    if (tol < 1) return 1;
    return (double)fat.lower.x <= (double)own.lower.x - tol && (double)fat.lower.y <= (double)own.lower.y - tol &&
           (double)fat.upper.x >= (double)own.upper.x + tol && (double)fat.upper.y >= (double)own.upper.y + tol;
}

/* A ray: the closest hit and every hit, checked against the scan. */
static void fsw_q_ray(fsw_state *s, ga2d_vec o, ga2d_vec t, ga2d_filter f, int mode, int meddle, int null_fn)
{
    ga2d_world *w = s->base.w;
    fsw_q q, q2;
    fsw_buf before;
    int saved, nf, zero, i, n;
    ga2d_vec end = ga2d_vec_add(o, t);
    ga2d_ray_result closest, plain;
    ga2d_result r, rc;
    ga2d_shape_id all[FSW_QMAX];
    memset(&q, 0, sizeof q);
    q.origin = o;
    q.translation = t;
    q.filter = f;
    q.mode = mode;
    q.meddle = meddle;
    nf = !fz_finite_vec(o) || !fz_finite_vec(t) || !fz_finite_vec(end);
    zero = t.x == 0 && t.y == 0;
    fsw_q_begin(s, &q, &before, &saved);
    r = ga2d_world_cast_ray(w, o, t, f, null_fn ? NULL : fsw_q_cast, &q);
    FSW_TRACE((stderr, "query ray (%g %g) + (%g %g) mode %d meddle %d null %d: %s, %d calls\n", (double)o.x, (double)o.y,
               (double)t.x, (double)t.y, mode, meddle, null_fn, ga2d_result_string(r), q.calls));
    FUZZ_CHECK(r == (nf ? GA2D_ERR_NOT_FINITE : zero || null_fn ? GA2D_ERR_INVALID_ARGUMENT : GA2D_OK));
    FUZZ_CHECK(ga2d_world_cast_ray(NULL, o, t, f, fsw_q_never, NULL) == (nf ? GA2D_ERR_NOT_FINITE : zero ? GA2D_ERR_INVALID_ARGUMENT : GA2D_ERR_INVALID_ARGUMENT));
    fsw_q_end(s, &before, saved);
    if (r != GA2D_OK) FUZZ_CHECK(q.calls == 0);
    if (mode == 3) FUZZ_CHECK(q.calls <= 1);
    memset(&closest, 0x5A, sizeof closest);
    q2 = q;
    fsw_q_begin(s, &q2, &before, &saved);
    rc = ga2d_world_cast_ray_closest_checked(w, o, t, f, &closest);
    plain = ga2d_world_cast_ray_closest(w, o, t, f);
    fsw_q_end(s, &before, saved);
    FUZZ_CHECK(rc == (nf ? GA2D_ERR_NOT_FINITE : zero ? GA2D_ERR_INVALID_ARGUMENT : GA2D_OK));
    FUZZ_CHECK(ga2d_world_cast_ray_closest_checked(w, o, t, f, NULL) != GA2D_OK);
    if (rc != GA2D_OK) {
        FUZZ_CHECK(!plain.hit && ga2d_shape_id_is_null(plain.shape));
        return;
    }
    FUZZ_CHECK(memcmp(&plain, &closest, sizeof plain) == 0);
    if (r != GA2D_OK || (mode != 0 && mode != 1) || q.lost) return;
    /* the scan: every live shape the filter sees, its own cast */
    n = fsw_q_all_shapes(w, all, FSW_QMAX);
    if (n < 0) return;
    {
        int hits = 0, best = -1, stale = 0;
        ga2d_real least = 2;
        for (i = 0; i < n; ++i) {
            ga2d_ray_result h;
            int k;
            if (!fsw_q_sees(&q, all[i])) continue;
            {
                ga2d_geometry g = ga2d_shape_geometry(w, all[i]);
                if (ga2d_ray_cast_shape(&g, ga2d_body_transform(w, ga2d_shape_body(w, all[i])), o, t, &h) != GA2D_OK) continue;
            }
            k = fsw_q_index(&q, all[i]);
            FSW_TRACE((stderr, "  scan: shape %u hit %d f %.9g; query %d f %.9g\n", all[i].index1, h.hit, (double)h.fraction, k,
                       k >= 0 ? (double)q.fraction[k] : -1.0));
#ifdef FUZZ_VERBOSE
            {
                ga2d_aabb fb = ga2d_shape_fat_aabb(w, all[i]);
                double S0;
                ga2d_aabb tb = fsw_q_shape_box(w, all[i], &S0);
                ga2d_body_id bb = ga2d_shape_body(w, all[i]);
                fprintf(stderr, "    type %d body %u (type %d awake %d) fat (%g %g)-(%g %g) own (%g %g)-(%g %g) point (%g %g)\n",
                        (int)ga2d_shape_get_type(w, all[i]), bb.index1, (int)ga2d_body_get_type(w, bb), ga2d_body_is_awake(w, bb),
                        (double)fb.lower.x, (double)fb.lower.y, (double)fb.upper.x, (double)fb.upper.y, (double)tb.lower.x,
                        (double)tb.lower.y, (double)tb.upper.x, (double)tb.upper.y, (double)h.point.x, (double)h.point.y);
            }
#endif
            if (!h.hit) {
                FUZZ_CHECK(k < 0);
                continue;
            }
            if (k < 0 && !fsw_q_in_tree_box(w, all[i], fsw_n1(o) + fsw_n1(t))) {
                stale = 1; /* outside its box: the query cannot see it */
                continue;
            }
            ++hits;
            FUZZ_CHECK(k >= 0 && q.fraction[k] == h.fraction);
            if (h.fraction < least) {
                least = h.fraction;
                best = i;
            }
        }
        FUZZ_CHECK(q.nseen == hits);
        FUZZ_CHECK(closest.hit == (hits > 0));
        FSW_TRACE((stderr, "  closest: hit %d shape %u f %.9g; scan least %.9g of %d\n", closest.hit, closest.shape.index1,
                   (double)closest.fraction, (double)least, hits));
        if (hits > 0) {
            /* one of the hits, with its own fraction; the least of them
               unless the tree's clipped box tests may round it away (the
               nearest shape within rounding of its box's edge, far
               out) */
            int kc = fsw_q_index(&q, closest.shape);
            FUZZ_CHECK(kc >= 0 && q.fraction[kc] == closest.fraction);
            FUZZ_CHECK(ga2d_body_id_equal(closest.body, ga2d_shape_body(w, closest.shape)));
            if (!stale && fsw_q_in_tree_box(w, all[best], fsw_n1(o) + fsw_n1(t))) FUZZ_CHECK(closest.fraction == least);
        }
    }
}

/* A shape's own box in double (the query's, not the broadphase's fat
   one), and the size its placement rounds by. */
static ga2d_aabb fsw_q_shape_box(ga2d_world *w, ga2d_shape_id id, double *S)
{
    ga2d_geometry g = ga2d_shape_geometry(w, id);
    ga2d_transform x = ga2d_body_transform(w, ga2d_shape_body(w, id));
    ga2d_vec pts[GA2D_MAX_POLYGON_VERTICES];
    ga2d_real r = 0;
    int n = 0, i;
    ga2d_aabb b;
    switch (g.type) {
    case GA2D_SHAPE_CIRCLE: pts[n++] = g.as.circle.center; r = g.as.circle.radius; break;
    case GA2D_SHAPE_CAPSULE: pts[n++] = g.as.capsule.center1; pts[n++] = g.as.capsule.center2; r = g.as.capsule.radius; break;
    case GA2D_SHAPE_POLYGON:
        for (i = 0; i < g.as.polygon.count; ++i) pts[n++] = g.as.polygon.vertices[i];
        r = g.as.polygon.radius;
        break;
    case GA2D_SHAPE_SEGMENT: pts[n++] = g.as.segment.point1; pts[n++] = g.as.segment.point2; break;
    default: pts[n++] = g.as.chain_segment.segment.point1; pts[n++] = g.as.chain_segment.segment.point2; break;
    }
    *S = fsw_n1(x.p) + (double)r;
    for (i = 0; i < n; ++i) {
        ga2d_vec p = ga2d_transform_apply(x, pts[i]);
        if (i == 0) b.lower = b.upper = p;
        if (p.x < b.lower.x) b.lower.x = p.x;
        if (p.y < b.lower.y) b.lower.y = p.y;
        if (p.x > b.upper.x) b.upper.x = p.x;
        if (p.y > b.upper.y) b.upper.y = p.y;
        if (fsw_n1(pts[i]) + fsw_n1(x.p) + (double)r > *S) *S = fsw_n1(pts[i]) + fsw_n1(x.p) + (double)r;
    }
    b.lower = ga2d_vec_sub(b.lower, ga2d_vec_make(r, r));
    b.upper = ga2d_vec_add(b.upper, ga2d_vec_make(r, r));
    return b;
}

static int fsw_q_boxes_meet(ga2d_aabb a, ga2d_aabb b, double grow)
{
    return (double)a.lower.x - grow <= (double)b.upper.x && (double)b.lower.x <= (double)a.upper.x + grow &&
           (double)a.lower.y - grow <= (double)b.upper.y && (double)b.lower.y <= (double)a.upper.y + grow;
}

/* A box: every shape whose own box meets it, and no other. */
static void fsw_q_aabb(fsw_state *s, ga2d_aabb box, ga2d_filter f, int mode, int meddle, int null_fn)
{
    ga2d_world *w = s->base.w;
    fsw_q q;
    fsw_buf before;
    int saved, nf, bad, i, n;
    ga2d_result r;
    ga2d_shape_id all[FSW_QMAX];
    memset(&q, 0, sizeof q);
    q.filter = f;
    q.mode = mode;
    q.meddle = meddle;
    nf = !fz_finite_vec(box.lower) || !fz_finite_vec(box.upper);
    bad = !(box.lower.x <= box.upper.x && box.lower.y <= box.upper.y);
    fsw_q_begin(s, &q, &before, &saved);
    r = ga2d_world_overlap_aabb(w, box, f, null_fn ? NULL : fsw_q_overlap, &q);
    fsw_q_end(s, &before, saved);
    FSW_TRACE((stderr, "query box (%g %g)-(%g %g) mode %d: %s, %d calls\n", (double)box.lower.x, (double)box.lower.y,
               (double)box.upper.x, (double)box.upper.y, mode, ga2d_result_string(r), q.calls));
    FUZZ_CHECK(r == (nf ? GA2D_ERR_NOT_FINITE : bad || null_fn ? GA2D_ERR_INVALID_ARGUMENT : GA2D_OK));
    if (r != GA2D_OK) {
        FUZZ_CHECK(q.calls == 0);
        return;
    }
    if (mode == 3) FUZZ_CHECK(q.calls <= 1);
    n = fsw_q_all_shapes(w, all, FSW_QMAX);
    for (i = 0; i < n; ++i) {
        double S;
        ga2d_aabb sb;
        int k = fsw_q_index(&q, all[i]);
        if (!fsw_q_sees(&q, all[i])) continue;
        sb = fsw_q_shape_box(w, all[i], &S);
        S += fsw_n1(box.lower) + fsw_n1(box.upper);
        if (k >= 0) FUZZ_CHECK(fsw_q_boxes_meet(sb, box, fsw_q_tol(S)));
        else if (mode != 3 && !q.lost && fsw_q_in_tree_box(w, all[i], S)) FUZZ_CHECK(!fsw_q_boxes_meet(sb, box, -fsw_q_tol(S)));
    }
}

/* A point: only shapes within rounding of it (never a segment), and
   every circle that surely holds it. */
static void fsw_q_point(fsw_state *s, ga2d_vec p, ga2d_filter f, int mode, int meddle)
{
    ga2d_world *w = s->base.w;
    fsw_q q;
    fsw_buf before;
    int saved, i, n;
    ga2d_result r;
    ga2d_shape_id all[FSW_QMAX];
    ga2d_shape_proxy pp = ga2d_make_proxy(&p, 1, 0);
    memset(&q, 0, sizeof q);
    q.filter = f;
    q.mode = mode;
    q.meddle = meddle;
    fsw_q_begin(s, &q, &before, &saved);
    r = ga2d_world_overlap_point(w, p, f, fsw_q_overlap, &q);
    fsw_q_end(s, &before, saved);
    FUZZ_CHECK(r == (fz_finite_vec(p) ? GA2D_OK : GA2D_ERR_NOT_FINITE));
    if (r != GA2D_OK) return;
    n = fsw_q_all_shapes(w, all, FSW_QMAX);
    for (i = 0; i < n; ++i) {
        ga2d_geometry g = ga2d_shape_geometry(w, all[i]);
        ga2d_transform x = ga2d_body_transform(w, ga2d_shape_body(w, all[i]));
        ga2d_shape_proxy sp = ga2d_shape_proxy_of(&g);
        ga2d_distance_result d;
        int k = fsw_q_index(&q, all[i]);
        double S, tol;
        /* GJK works in the shape's own coordinates, as large as its
           vertices: its distance rounds by eps of them (a 2e8 m box
           holding a point 4 m inside it measured 4 m away in float) */
        (void)fsw_q_shape_box(w, all[i], &S);
        tol = fsw_q_tol(fsw_n1(p) + S + 2 * FSW_QMAX);
        if (!fsw_q_sees(&q, all[i])) continue;
        if (k >= 0) {
            FUZZ_CHECK(g.type != GA2D_SHAPE_SEGMENT && g.type != GA2D_SHAPE_CHAIN_SEGMENT);
            if (ga2d_shape_distance(&sp, x, &pp, ga2d_transform_identity(), NULL, &d) == GA2D_OK)
                FUZZ_CHECK((double)d.distance <= tol);
        } else if (mode != 3 && !q.lost && g.type == GA2D_SHAPE_CIRCLE && fsw_q_in_tree_box(w, all[i], fsw_n1(p))) {
            ga2d_vec c = ga2d_transform_apply(x, g.as.circle.center);
            double dx = (double)p.x - (double)c.x, dy = (double)p.y - (double)c.y;
            FUZZ_CHECK(!(hypot(dx, dy) < (double)g.as.circle.radius - tol));
        }
    }
}

/* A proxy from the input: a circle, a capsule, a box or any points;
   ordinary sizes, or anything. */
static ga2d_shape_proxy fsw_q_proxy(fsw_state *s, int *clean)
{
    fw_state *b = &s->base;
    ga2d_vec pts[GA2D_MAX_POLYGON_VERTICES + 1];
    unsigned k = fz_u8(&b->rd);
    int n, i, wild = k >= 224;
    ga2d_real r;
    if (k % 4 == 0) n = 1;
    else if (k % 4 == 1) n = 2;
    else if (k % 4 == 2) n = 4;
    else n = (int)(fz_u8(&b->rd) % (GA2D_MAX_POLYGON_VERTICES + 2));
    for (i = 0; i < n; ++i) pts[i] = wild ? fw_vec(b, 2, 1) : fsw_vec(s, 0);
    if (k % 4 == 2 && !wild) {
        ga2d_real hx = fz_narrow((double)(1 + fz_u8(&b->rd) % 64) / 32), hy = fz_narrow((double)(1 + fz_u8(&b->rd) % 64) / 32);
        pts[0] = ga2d_vec_make(-hx, -hy);
        pts[1] = ga2d_vec_make(hx, -hy);
        pts[2] = ga2d_vec_make(hx, hy);
        pts[3] = ga2d_vec_make(-hx, hy);
    }
    r = wild ? fz_real(&b->rd, 1) : fz_narrow((double)fz_u8(&b->rd) / 256);
    *clean = !wild && n >= 1;
    return ga2d_make_proxy(pts, n, r);
}

static int fsw_q_proxy_refused(const ga2d_shape_proxy *p)
{
    int i;
    if (p->count < 1 || p->count > GA2D_MAX_POLYGON_VERTICES || !fz_finite((double)p->radius) || p->radius < 0) return 1;
    for (i = 0; i < p->count; ++i)
        if (!fz_finite_vec(p->points[i])) return 1;
    return 0;
}

/* Finite, but past the bounds a shape and a body keep (a proxy point or
   radius, the placement or a cast's end beyond GA2D_MAX_COORDINATE): the
   query refuses it.  The end is summed in ga2d_real, as the library does. */
static int fsw_q_beyond(const ga2d_shape_proxy *p, ga2d_transform x, ga2d_vec t, int cast)
{
    const double M = (double)GA2D_MAX_COORDINATE;
    ga2d_vec end = ga2d_vec_add(x.p, t);
    int i, out = fabs((double)p->radius) > M || fabs((double)x.p.x) > M || fabs((double)x.p.y) > M;
    for (i = 0; i < p->count; ++i) out |= fabs((double)p->points[i].x) > M || fabs((double)p->points[i].y) > M;
    return out || (cast && (fabs((double)end.x) > M || fabs((double)end.y) > M));
}

/* A shape overlap or a shape cast. */
static void fsw_q_shape_query(fsw_state *s, int cast, ga2d_filter f, int mode, int meddle)
{
    fw_state *b = &s->base;
    ga2d_world *w = b->w;
    fsw_q q;
    fsw_buf before;
    int saved, clean, i, n, wild = fz_u8(&b->rd) < 32;
    ga2d_shape_proxy px = fsw_q_proxy(s, &clean);
    ga2d_transform x;
    ga2d_vec t = fw_vec(b, 8, wild);
    ga2d_result r;
    ga2d_shape_id all[FSW_QMAX];
    x.p = fw_vec(b, 4, wild);
    x.q = ga2d_rotor_from_angle(fw_val(b, 4, 0));
    if (wild && fz_u8(&b->rd) < 64) {
        x.q.c = fz_real(&b->rd, 1);
        x.q.s = fz_real(&b->rd, 1);
    }
    memset(&q, 0, sizeof q);
    q.filter = f;
    q.mode = mode;
    q.meddle = meddle;
    q.shape_cast = cast;
    fsw_q_begin(s, &q, &before, &saved);
    r = cast ? ga2d_world_cast_shape(w, &px, x, t, f, fsw_q_cast, &q) : ga2d_world_overlap_shape(w, &px, x, f, fsw_q_overlap, &q);
    fsw_q_end(s, &before, saved);
    FSW_TRACE((stderr, "query shape cast %d count %d r %g at (%g %g) t (%g %g): %s, %d calls\n", cast, px.count, (double)px.radius,
               (double)x.p.x, (double)x.p.y, (double)t.x, (double)t.y, ga2d_result_string(r), q.calls));
    FUZZ_CHECK((int)r >= 0 && r < GA2D_RESULT_COUNT);
    if (fsw_q_proxy_refused(&px) || !fz_finite_vec(x.p) || !fw_rotor_ok(x.q) || (cast && !fz_finite_vec(t)))
        FUZZ_CHECK(r == GA2D_ERR_NOT_FINITE || r == GA2D_ERR_INVALID_ARGUMENT);
    else if (fsw_q_beyond(&px, x, t, cast))
        FUZZ_CHECK(r != GA2D_OK);
    else if (!wild)
        FUZZ_CHECK(r == GA2D_OK); /* a unit rotor, ordinary sizes */
    else
        FUZZ_CHECK(r == GA2D_OK || r == GA2D_ERR_INVALID_ARGUMENT || r == GA2D_ERR_NOT_FINITE || r == GA2D_ERR_TOO_LARGE);
    FUZZ_CHECK(ga2d_world_overlap_shape(w, &px, x, f, NULL, NULL) != GA2D_OK);
    FUZZ_CHECK(ga2d_world_overlap_shape(w, NULL, x, f, fsw_q_never_overlap, NULL) == GA2D_ERR_INVALID_ARGUMENT);
    if (r != GA2D_OK) {
        FUZZ_CHECK(q.calls == 0);
        return;
    }
    if (mode == 3) FUZZ_CHECK(q.calls <= 1);
    if (cast || !clean) return;
    /* an overlap: only shapes within rounding of the proxy */
    n = fsw_q_all_shapes(w, all, FSW_QMAX);
    for (i = 0; i < n; ++i) {
        ga2d_geometry g;
        ga2d_shape_proxy sp;
        ga2d_distance_result d;
        ga2d_transform xs;
        if (fsw_q_index(&q, all[i]) < 0) continue;
        g = ga2d_shape_geometry(w, all[i]);
        sp = ga2d_shape_proxy_of(&g);
        xs = ga2d_body_transform(w, ga2d_shape_body(w, all[i]));
        if (ga2d_shape_distance(&sp, xs, &px, x, NULL, &d) == GA2D_OK)
            FUZZ_CHECK((double)d.distance <= fsw_q_tol(fsw_n1(xs.p) + fsw_n1(x.p) + 2 * FSW_QMAX));
    }
}

/* The body list: every live body once, in id index order; a short
   buffer gets the first ones; NULL counts. */
static void fsw_q_bodies(fsw_state *s, int cap)
{
    ga2d_world *w = s->base.w;
    ga2d_body_id ids[FSW_QMAX], some[FSW_QMAX];
    int n = ga2d_world_get_bodies(w, ids, FSW_QMAX), i, k;
    FUZZ_CHECK(n == ga2d_world_get_counters(w).body_count && n == ga2d_world_body_count(w));
    FUZZ_CHECK(ga2d_world_get_bodies(w, NULL, 0) == n && ga2d_world_get_bodies(NULL, ids, FSW_QMAX) == 0);
    for (i = 0; i < n && i < FSW_QMAX; ++i) {
        FUZZ_CHECK(ga2d_body_is_valid(w, ids[i]));
        if (i > 0) FUZZ_CHECK(ids[i].index1 > ids[i - 1].index1);
    }
    for (i = 0; i < s->base.nids; ++i)
        if (ga2d_body_is_valid(w, s->base.ids[i]) && n <= FSW_QMAX) {
            int found = 0;
            for (k = 0; k < n; ++k) found |= ga2d_body_id_equal(ids[k], s->base.ids[i]);
            FUZZ_CHECK(found);
        }
    if (cap > FSW_QMAX) cap = FSW_QMAX;
    memset(some, 0, sizeof some);
    FUZZ_CHECK(ga2d_world_get_bodies(w, some, cap) == n);
    for (i = 0; i < cap && i < n; ++i) FUZZ_CHECK(ga2d_body_id_equal(some[i], ids[i]));
    for (; i < cap; ++i) FUZZ_CHECK(ga2d_body_id_is_null(some[i])); /* past the count: untouched */
}

/* The world's continuous counters after a step. */
static void fsw_q_check_continuous(fsw_state *s)
{
    ga2d_world_counters c = ga2d_world_get_counters(s->base.w);
    FUZZ_CHECK(c.continuous_hits >= 0 && c.continuous_hits <= c.continuous_bodies);
    FUZZ_CHECK(c.continuous_bodies <= c.body_count);
    if (s->ccd_known && !s->ccd_on) FUZZ_CHECK(c.continuous_bodies == 0 && c.continuous_hits == 0);
}

static ga2d_filter fsw_q_filter(fsw_state *s)
{
    fz_reader *r = &s->base.rd;
    ga2d_filter f = ga2d_default_filter();
    unsigned k = fz_u8(r);
    if (k < 192) return f;
    f.category_bits = (uint32_t)1u << (k % 4);
    f.mask_bits = fz_u8(r) < 128 ? 0xFFFFFFFFu : (uint32_t)fz_u8(r);
    f.group_index = (int32_t)(int8_t)fz_u8(r) % 3;
    return f;
}

/* One query operation. */
static void fsw_query_op(fsw_state *s)
{
    fw_state *b = &s->base;
    ga2d_world *w = b->w;
    fz_reader *rd = &b->rd;
    unsigned k = fz_u8(rd), how = fz_u8(rd);
    int mode = (int)(how % 5), meddle = (how >> 3) & 1, wild = ((how >> 4) & 3) == 3;
    ga2d_filter f = fsw_q_filter(s);
    switch (k % 10) {
    case 0: case 1: {
        ga2d_vec o = fw_vec(b, 4, wild), t = fw_vec(b, 8, wild);
        if ((how >> 6) == 3) t = ga2d_vec_make(0, 0);
        fsw_q_ray(s, o, t, f, mode, meddle, (how >> 6) == 2 && (how & 4));
        break;
    }
    case 2: {
        ga2d_aabb box;
        box.lower = fw_vec(b, 4, wild);
        box.upper = ga2d_vec_add(box.lower, ga2d_vec_make(fw_pos(b, 8, wild), fw_pos(b, 8, wild)));
        if ((how >> 6) == 3) {
            ga2d_vec v = box.lower;
            box.lower = box.upper;
            box.upper = v;
        }
        fsw_q_aabb(s, box, f, mode, meddle, (how >> 6) == 2 && (how & 4));
        break;
    }
    case 3: fsw_q_point(s, fw_vec(b, 4, wild), f, mode, meddle); break;
    case 4: case 5: fsw_q_shape_query(s, (int)(k % 10) == 5, f, mode, meddle); break;
    case 6: fsw_q_bodies(s, (int)fz_u8(rd) % 64); break;
    case 7: {
        int on = (int)(how % 4) - 1;
        ga2d_result r = ga2d_world_enable_continuous(w, on);
        FUZZ_CHECK(r == GA2D_OK);
        FUZZ_CHECK(ga2d_world_enable_continuous(NULL, on) == GA2D_ERR_INVALID_ARGUMENT);
        s->ccd_known = 1;
        s->ccd_on = on != 0;
        break;
    }
    case 8: {
        ga2d_body_id id = fw_id(b);
        int on = (int)(how % 4) - 1, valid = ga2d_body_is_valid(w, id);
        ga2d_result r;
        fsw_guard gd;
        fsw_guard_begin(s, &gd);
        r = ga2d_body_set_bullet(w, id, on);
        FUZZ_CHECK(r == (valid ? GA2D_OK : GA2D_ERR_STALE_ID));
        fsw_guard_end(s, &gd, r);
        FUZZ_CHECK(ga2d_body_is_bullet(w, id) == (valid && on != 0));
        if (fz_u8(rd) < 32) fsw_round_trip(s);
        break;
    }
    default: {
        /* a fast body: 10 m/s to the speed cap, a bullet or not, then a step */
        static const double speeds[6] = {10, 50, 100, 300, 1000, GA2D_MAX_LINEAR_SPEED};
        ga2d_body_id id = fw_id(b);
        double a = (double)fz_u8(rd) * (6.283185307179586 / 256), v = speeds[how % 6];
        if (ga2d_body_get_type(w, id) == GA2D_BODY_DYNAMIC) {
            FUZZ_CHECK(ga2d_body_set_velocity(w, id, ga2d_vec_make(fz_narrow(v * cos(a)), fz_narrow(v * sin(a)))) == GA2D_OK);
            if (how & 64) FUZZ_CHECK(ga2d_body_set_bullet(w, id, 1) == GA2D_OK);
        }
        fsw_step(s);
        break;
    }
    }
}

/* At the end of every input, reading no byte: rays between the tracked
   bodies, a box around each, the body list. */
static void fsw_query_final(fsw_state *s)
{
    ga2d_world *w = s->base.w;
    int i;
    fsw_q_bodies(s, 3);
    for (i = 0; i < s->base.nids && i < 6; ++i) {
        ga2d_body_id a = s->base.ids[i], c = s->base.ids[(i + 1) % s->base.nids];
        ga2d_vec o = ga2d_body_position(w, a), t = ga2d_vec_sub(ga2d_body_position(w, c), o);
        if (!ga2d_body_is_valid(w, a) || !ga2d_body_is_valid(w, c)) continue;
        if (t.x == 0 && t.y == 0) t = ga2d_vec_make(1, 0);
        fsw_q_ray(s, o, t, ga2d_default_filter(), i & 1, 0, 0);
        fsw_q_aabb(s, ga2d_body_fat_aabb(w, a), ga2d_default_filter(), 0, 0, 0);
        fsw_q_point(s, o, ga2d_default_filter(), 0, 0);
    }
}

/* ------------------------------------------------------------ one input */
static int fuzz_shape_world_one(const uint8_t *data, size_t size)
{
    fsw_state *s = (fsw_state *)calloc(1, sizeof(fsw_state));
    fw_state *b;
    ga2d_world_def d;
    ga2d_result valid;
    int i, n, ops = 0;
    unsigned k;
    (void)fuzz_world_one; /* fuzz_world.h's entry: not this harness's */
    if (!s) return 0;
    b = &s->base;
    fz_init(&b->rd, data, size);
    d = fw_world_def(b);
    /* what shapes brought to the world def */
    k = fz_u8(&b->rd);
    if (k & 1) {
        d.pre_solve = fsw_pre_solve;
        d.pre_solve_context = &s->cb;
    }
    if (k & 2) d.hit_event_threshold = (k & 4) ? fz_real(&b->rd, 1) : fz_narrow((double)fz_u8(&b->rd) / 32);
    s->cb.mode = (int)((k >> 3) % 3);
    s->cb.probe = (k >> 5) & 1;
    s->cb.scribble = (k >> 6) & 1;
    s->cb.s = s;
    valid = ga2d_world_def_validate(&d);
    b->w = ga2d_world_create(&d);
    FSW_TRACE((stderr, "world: pre-solve %d mode %d probe %d hit threshold %g: %s\n", d.pre_solve != NULL, s->cb.mode,
               s->cb.probe, (double)d.hit_event_threshold, ga2d_result_string(valid)));
    if (!b->w) {
        FUZZ_CHECK(valid != GA2D_OK || b->alloc.failures > 0);
        FUZZ_CHECK(b->alloc.live_bytes == 0 && b->alloc.live_blocks == 0);
        free(s);
        return 0;
    }
    FUZZ_CHECK(valid == GA2D_OK);
    s->cb.w = b->w;
    s->def = d;
    s->has_pre_solve = d.pre_solve != NULL;
    s->field_on = d.force_callback != NULL;
    s->hit_threshold = d.hit_event_threshold != 0 ? d.hit_event_threshold : (ga2d_real)GA2D_DEFAULT_HIT_EVENT_THRESHOLD;
    b->substeps = d.substeps ? d.substeps : 4;
    b->units = d.length_units_per_meter > 0 ? (double)d.length_units_per_meter : 1;
    b->passes = d.solver == GA2D_SOLVER_SOFT_STEP ? 2
                : (d.velocity_iterations ? d.velocity_iterations : 8) + (d.position_iterations ? d.position_iterations : 3);
    if (b->passes < 2) b->passes = 2;
    b->rk4 = d.integrator == GA2D_INTEGRATOR_RK4;

    n = fz_pick(&b->rd, 12);
    for (i = 0; i < n; ++i) {
        if (fz_u8(&b->rd) & 1) fw_create(b);
        else fsw_create_bare(s);
    }
    while (fz_more(&b->rd) && ops++ < FSW_MAX_OPS) {
        int op = fz_pick(&b->rd, 40);
        long failures = b->alloc.failures;
        if (op < 8) fsw_step(s);
        else if (op < 10) {
            if (op == 8) fw_create(b);
            else fsw_create_bare(s);
            fsw_dedupe_bodies(s);
        } else if (op < 16) fsw_shape_create(s);
        else if (op < 18) fsw_shape_destroy(s);
        else if (op < 20) fsw_shape_set(s);
        else if (op < 22) fsw_chain_create(s);
        else if (op == 22) fsw_chain_destroy(s);
        else if (op < 30) {
            int bop = fz_pick(&b->rd, 15);
            fw_body_op(b, bop);
            if (bop == 13 && b->alloc.failures != failures) s->pending_oom = 1; /* a destruction's end events */
            if (bop == 3) s->mass_set = 1;
        } else if (op < 32) {
            int wop = fz_pick(&b->rd, 8);
            /* fw_world_op's 8th sets the force callback by its next byte's bit 4 */
            if (wop == 7) s->field_on = b->rd.i < b->rd.n && ((b->rd.p[b->rd.i] >> 4) & 1);
            fw_world_op(b, wop);
        }
        else if (op == 32) fsw_queries(s);
        else if (op == 33) fsw_round_trip(s);
        else if (op == 34) fsw_checkpoint(s);
        else if (op == 35) fsw_replay(s);
        else if (op == 36) {
            unsigned m = fz_u8(&b->rd);
            s->cb.mode = (int)(m % 3);
            s->cb.probe = (m >> 2) & 1;
            s->cb.scribble = (m >> 3) & 1;
        } else if (op == 37) {
            /* one of the next few allocations fails (whichever call makes it) */
            b->alloc.fail_at = b->alloc.attempts + 1 + fz_pick(&b->rd, 4);
        } else if (op == 38) fsw_joint_op(s);
        else if (fz_more(&b->rd) && b->rd.p[b->rd.i] >= FSW_QUERY_MARK) {
            /* the query ops (issue 25): op 39 and a marked byte, so older
               inputs (op 39 made a shape) keep their meaning */
            ++b->rd.i;
            fsw_query_op(s);
        } else fsw_shape_create(s);
        /* a load may bring back another continuous switch */
        if (op >= 33 && op <= 35) s->ccd_known = 0;
        /* a destroyed body's joints are stale */
        if (op >= 23 && op < 30 && s->njoints > 0) fsw_check_joints(s, 0);
    }
    /* a couple of ordinary steps, the queries, a round trip */
    for (i = 0; i < 2; ++i) {
        ga2d_result r;
        (void)fsw_step_dt(s, (ga2d_real)(1.0 / 60), &r);
    }
    fsw_queries(s);
    fsw_query_final(s);
    fsw_round_trip(s);
    ga2d_world_destroy(b->w);
    /* every byte back, each block freed with its own size */
    FUZZ_CHECK(b->alloc.live_bytes == 0 && b->alloc.live_blocks == 0);
    free(s->ckpt.p);
    free(s);
    return 0;
}

#endif
