/* test_threads.c - the step on the user's task system (DESIGN §13): the
   same bits for any worker count and any way of cutting and ordering the
   ranges, the def's task fields checked, and a task system that calls the
   world while a stage runs is refused.

   Task systems: examples/task_pool.h with 1 to 4 workers (threads); one
   that runs the ranges itself on this thread, last range first, at the
   least range the step allows (so a stage that wrote another range's
   items, or depended on their order, would show); one that runs them only
   when finished, last range first (so work the step does between the two
   calls sees none of the job done); one that runs them all at once and
   returns NULL. */
#include "test.h"
#include "determinism_scene.h"
#define TASK_POOL_IMPLEMENTATION
#include "../examples/task_pool.h"

/* ------------------------------------------------- a backwards system */
typedef struct backwards {
    int calls, ranges, items, bad;
    int probe;          /* call the world from inside enqueue */
    ga2d_world *world;
    ga2d_result probed; /* what the world answered */
} backwards;

static void *backwards_enqueue(ga2d_task_fn *task, int count, int min_range, void *context, void *user)
{
    backwards *b = (backwards *)user;
    int range = min_range < 1 ? 1 : min_range, ranges = (count + range - 1) / range, k, *seen;
    ++b->calls;
    if (b->probe && b->world) {
        ga2d_body_def d = ga2d_default_body_def();
        b->probed = ga2d_world_step(b->world, (ga2d_real)1 / 60);
        if (ga2d_world_set_gravity(b->world, ga2d_vec_make(0, 0)) != GA2D_ERR_LOCKED) b->probed = GA2D_OK;
        if (!ga2d_body_id_is_null(ga2d_body_create(b->world, &d))) b->probed = GA2D_OK;
    }
    seen = (int *)calloc((size_t)(count > 0 ? count : 1), sizeof *seen);
    for (k = ranges - 1; k >= 0; --k) { /* last first; workers 0..3 in turn */
        int start = k * range, end = start + range < count ? start + range : count, i;
        task(start, end, k % 4, context);
        for (i = start; seen && i < end; ++i) ++seen[i];
        ++b->ranges;
    }
    for (k = 0; seen && k < count; ++k) b->bad += seen[k] != 1;
    free(seen);
    b->items += count;
    return b; /* a handle: finish is called */
}

static void backwards_finish(void *task, void *user)
{
    if (task != user) ((backwards *)user)->bad += 1000;
}

/* runs every range at once, here, and returns NULL: finish must not be called */
static void *inline_enqueue(ga2d_task_fn *task, int count, int min_range, void *context, void *user)
{
    (void)min_range;
    ++*(int *)user;
    task(0, count, 0, context);
    return NULL;
}

static void inline_finish(void *task, void *user)
{
    (void)task;
    *(int *)user += 1000000; /* never: enqueue returned NULL */
}

/* --------------------------------------------------- a deferred system */
/* Runs nothing when a job is enqueued and all of it, last range first, in
   finish (as a job system that works only when waited on): whatever the
   step did on its own thread between the two calls would see none of the
   job's work done, the opposite of the backwards system, which has done
   all of it by then. */
typedef struct deferred {
    ga2d_task_fn *task;
    void *context;
    int count, range, pending, bad, jobs;
} deferred;

static void *deferred_enqueue(ga2d_task_fn *task, int count, int min_range, void *context, void *user)
{
    deferred *d = (deferred *)user;
    d->bad += d->pending; /* one job at a time */
    d->task = task;
    d->context = context;
    d->count = count;
    d->range = min_range < 1 ? 1 : min_range;
    d->pending = 1;
    return d;
}

static void deferred_finish(void *task, void *user)
{
    deferred *d = (deferred *)user;
    int start;
    if (task != user || !d->pending) {
        d->bad += 1000;
        return;
    }
    d->pending = 0;
    ++d->jobs;
    for (start = (d->count - 1) / d->range * d->range; start >= 0; start -= d->range)
        d->task(start, start + d->range < d->count ? start + d->range : d->count, 0, d->context);
}

/* --------------------------------------------------- a big mixed scene */
/* Enough of everything that every split stage is cut into many ranges: a
   pyramid of base 30 (465 boxes, about 1 400 contacts), 60 discs dropped
   on it, and a chain of 20 links on revolute joints swinging into it
   from a post; and, on a ground of their own, 320 stacks of two small
   boxes, so that the solver's first colours are long enough to be handed
   over (each a stack's ground contacts, then their middle ones: 320
   constraints, 80 groups, past GA2D__COLOUR_MIN); and far off, a net of
   28 x 28 discs on revolute joints to their left and upper neighbours,
   hung from its top row (static), whose joints' colours are long enough
   to be handed over too (1 485 joints, about 370 a colour: 24 blocks of
   GA2D__JOINT_BLOCK).  Hash: every body's state, as the determinism
   scene's. */
#define BIG_BASE 30
#define BIG_DISCS 60
#define BIG_LINKS 20
#define BIG_STACKS 320
#define BIG_NET 28
#define BIG_STEPS 240
#define BIG_MAX (1 + BIG_BASE * (BIG_BASE + 1) / 2 + BIG_DISCS + BIG_LINKS + 1 + 1 + 2 * BIG_STACKS + BIG_NET * BIG_NET)

/* The net: BIG_NET x BIG_NET discs 0.5 apart, each on a revolute joint
   to its left and its upper neighbour at the point between them, the top
   row static (and not joined along).  Its ids go to ids + *n.  0 if a joint was refused. */
static int big_net(ga2d_world *w, ga2d_body_id *ids, int *n)
{
    ga2d_body_def d = ga2d_default_body_def();
    ga2d_shape_def sd = ga2d_default_shape_def();
    ga2d_circle disc;
    int row, k, first = *n, ok = 1;
    disc.center = ga2d_vec_make(0, 0);
    disc.radius = (ga2d_real)0.15;
    for (row = 0; row < BIG_NET; ++row)
        for (k = 0; k < BIG_NET; ++k) {
            ga2d_body_id id;
            ga2d_revolute_joint_def j = ga2d_default_revolute_joint_def();
            d.type = row == 0 ? GA2D_BODY_STATIC : GA2D_BODY_DYNAMIC;
            d.position = ga2d_vec_make((ga2d_real)(-200 + 0.5 * k), (ga2d_real)(60 - 0.5 * row));
            id = ids[(*n)++] = ga2d_body_create(w, &d);
            ga2d_shape_create_circle(w, id, &sd, &disc);
            j.body_b = id;
            if (k > 0 && row > 0) { /* two static bodies take no joint */
                j.body_a = ids[first + row * BIG_NET + k - 1];
                j.local_anchor_a = ga2d_vec_make((ga2d_real)0.25, 0);
                j.local_anchor_b = ga2d_vec_make((ga2d_real)-0.25, 0);
                ok = ok && !ga2d_joint_id_is_null(ga2d_revolute_joint_create(w, &j));
            }
            if (row > 0) {
                j.body_a = ids[first + (row - 1) * BIG_NET + k];
                j.local_anchor_a = ga2d_vec_make(0, (ga2d_real)-0.25);
                j.local_anchor_b = ga2d_vec_make(0, (ga2d_real)0.25);
                ok = ok && !ga2d_joint_id_is_null(ga2d_revolute_joint_create(w, &j));
            }
        }
    return ok;
}

static uint64_t big_hash(ga2d_world *w, const ga2d_body_id *ids, int n)
{
    uint64_t h = 14695981039346656037ull;
    int i;
    for (i = 0; i < n; ++i) {
        ga2d_vec x = ga2d_body_position(w, ids[i]), v = ga2d_body_velocity(w, ids[i]);
        ga2d_rotor q = ga2d_body_rotor(w, ids[i]);
        ga2d_real om = ga2d_body_angular_velocity(w, ids[i]);
        h = dscene_fnv(h, &x, sizeof x);
        h = dscene_fnv(h, &q, sizeof q);
        h = dscene_fnv(h, &v, sizeof v);
        h = dscene_fnv(h, &om, sizeof om);
    }
    return h;
}

/* Steps the big scene in a world made from wd; returns its hash (0: not
   built) and the manifolds carried over the run in *carried, and leaves
   the contacts solved over the run in big_solved (its stacks fall asleep
   on their ground: those contacts are not solved). */
static long big_solved;
static uint64_t big_run(const ga2d_world_def *wd, long *carried)
{
    ga2d_world *w = ga2d_world_create(wd);
    ga2d_body_id *ids = (ga2d_body_id *)malloc(sizeof *ids * BIG_MAX);
    ga2d_body_def d = ga2d_default_body_def();
    ga2d_shape_def sd = ga2d_default_shape_def();
    uint64_t h = 0;
    int n = 0, row, i, ok = w != NULL && ids != NULL;
    *carried = big_solved = 0;
    if (ok) {
        d.polygon = ga2d_polygon_box(40, (ga2d_real)0.5);
        d.position = ga2d_vec_make(0, (ga2d_real)-0.5);
        ids[n++] = ga2d_body_create(w, &d);
        d.type = GA2D_BODY_DYNAMIC;
        d.polygon = ga2d_polygon_box((ga2d_real)0.5, (ga2d_real)0.5);
        for (row = 0; row < BIG_BASE; ++row)
            for (i = 0; i < BIG_BASE - row; ++i) {
                d.position = ga2d_vec_make((ga2d_real)(i - 0.5 * (BIG_BASE - row - 1)) * (ga2d_real)1.05, (ga2d_real)(0.5 + row));
                ids[n++] = ga2d_body_create(w, &d);
            }
        d.polygon.count = 0;
        for (i = 0; i < BIG_DISCS; ++i) {
            ga2d_circle c;
            c.center = ga2d_vec_make(0, 0);
            c.radius = (ga2d_real)0.3;
            d.position = ga2d_vec_make((ga2d_real)(-9 + 0.3 * i), (ga2d_real)(BIG_BASE + 3 + (i % 3)));
            ids[n] = ga2d_body_create(w, &d);
            ga2d_shape_create_circle(w, ids[n++], &sd, &c);
        }
        /* the chain: a post, then links to the left of the pyramid */
        d.type = GA2D_BODY_STATIC;
        d.position = ga2d_vec_make(-25, 25);
        ids[n++] = ga2d_body_create(w, &d);
        d.type = GA2D_BODY_DYNAMIC;
        d.polygon = ga2d_polygon_box((ga2d_real)0.5, (ga2d_real)0.1);
        for (i = 0; i < BIG_LINKS; ++i) {
            ga2d_revolute_joint_def j = ga2d_default_revolute_joint_def();
            d.position = ga2d_vec_make((ga2d_real)(-24.5 + i), 25);
            ids[n] = ga2d_body_create(w, &d);
            j.body_a = ids[n - 1];
            j.body_b = ids[n];
            j.local_anchor_a = ga2d_vec_make(i == 0 ? 0 : (ga2d_real)0.5, 0);
            j.local_anchor_b = ga2d_vec_make((ga2d_real)-0.5, 0);
            ok = ok && !ga2d_joint_id_is_null(ga2d_revolute_joint_create(w, &j));
            ++n;
        }
        /* the stacks' ground, right of the pyramid, and the stacks */
        d.type = GA2D_BODY_STATIC;
        d.polygon = ga2d_polygon_box(100, (ga2d_real)0.5);
        d.position = ga2d_vec_make(150, (ga2d_real)-0.5);
        ids[n++] = ga2d_body_create(w, &d);
        d.type = GA2D_BODY_DYNAMIC;
        d.polygon = ga2d_polygon_box((ga2d_real)0.2, (ga2d_real)0.2);
        for (i = 0; i < 2 * BIG_STACKS; ++i) {
            d.position = ga2d_vec_make((ga2d_real)(55 + 0.6 * (i / 2)), (ga2d_real)(0.2 + 0.4 * (i % 2)));
            ids[n++] = ga2d_body_create(w, &d);
        }
        ok = ok && big_net(w, ids, &n);
        for (i = 0; ok && i < BIG_STEPS; ++i) {
            ok = ga2d_world_step(w, (ga2d_real)1 / 60) == GA2D_OK;
            *carried += ga2d_world_get_counters(w).manifolds_carried;
            big_solved += ga2d_world_get_counters(w).constraint_count;
        }
        if (ok) h = big_hash(w, ids, n);
    }
    ga2d_world_destroy(w);
    free(ids);
    return h;
}

static ga2d_world_def with_pool(task_pool *p)
{
    ga2d_world_def wd = ga2d_default_world_def();
    wd.worker_count = task_pool_workers(p);
    wd.enqueue_task = task_pool_enqueue;
    wd.finish_task = task_pool_finish;
    wd.user_task_context = p;
    return wd;
}

static ga2d_world_def with_backwards(backwards *b)
{
    ga2d_world_def wd = ga2d_default_world_def();
    memset(b, 0, sizeof *b);
    wd.worker_count = 4;
    wd.enqueue_task = backwards_enqueue;
    wd.finish_task = backwards_finish;
    wd.user_task_context = b;
    return wd;
}

/* The determinism scene (with churn, 600 steps) gives the one hash with
   1 to 4 pooled workers, backwards and inline as without a task system. */
static void any_worker_count_same_bits(void)
{
    int asleep, workers, calls = 0;
    uint64_t want = dscene_run(1, &asleep);
    backwards b;
    ga2d_world_def wd;
    CHECK(want != 0);
    for (workers = 1; workers <= 4; ++workers) {
        task_pool *p = task_pool_create(workers);
        dscene s;
        int step;
        CHECK(p != NULL);
        if (!p) continue;
        wd = with_pool(p);
        CHECK(dscene_build_in(&s, &wd));
        for (step = 0; step < DSCENE_STEPS; ++step) {
            dscene_churn(&s, step);
            ga2d_world_step(s.w, (ga2d_real)1 / 60);
        }
        if (dscene_hash(&s) != want)
            test_fail(__FILE__, __LINE__, "%d workers: hash %016llx, %016llx without", workers, (unsigned long long)dscene_hash(&s),
                      (unsigned long long)want);
        ga2d_world_destroy(s.w);
        task_pool_destroy(p);
    }
    {
        dscene s;
        int step;
        wd = with_backwards(&b);
        CHECK(dscene_build_in(&s, &wd));
        for (step = 0; step < DSCENE_STEPS; ++step) {
            dscene_churn(&s, step);
            ga2d_world_step(s.w, (ga2d_real)1 / 60);
        }
        CHECK(dscene_hash(&s) == want);
        CHECK(b.bad == 0);
        ga2d_world_destroy(s.w);
        wd = ga2d_default_world_def();
        wd.worker_count = 2;
        wd.enqueue_task = inline_enqueue;
        wd.finish_task = inline_finish;
        wd.user_task_context = &calls;
        CHECK(dscene_build_in(&s, &wd));
        for (step = 0; step < DSCENE_STEPS; ++step) {
            dscene_churn(&s, step);
            ga2d_world_step(s.w, (ga2d_real)1 / 60);
        }
        CHECK(dscene_hash(&s) == want);
        CHECK(calls < 1000000); /* finish never called after a NULL handle */
        ga2d_world_destroy(s.w);
    }
}

/* The big scene: the same bits and the same count of carried manifolds
   with every task system, and the stages really were cut (the backwards
   system saw many ranges, each item once). */
static void big_scene_same_bits(void)
{
    ga2d_world_def wd = ga2d_default_world_def();
    long carried, want_carried, want_solved;
    uint64_t want = big_run(&wd, &want_carried);
    backwards b;
    int workers;
    want_solved = big_solved;
    CHECK(want != 0);
    CHECK(want_carried > 0); /* the counter the split stage sums is exercised */
    for (workers = 2; workers <= 4; ++workers) {
        task_pool *p = task_pool_create(workers);
        CHECK(p != NULL);
        if (!p) continue;
        wd = with_pool(p);
        if (big_run(&wd, &carried) != want || carried != want_carried || big_solved != want_solved)
            test_fail(__FILE__, __LINE__, "%d workers: the big scene differs (carried %ld, %ld without; solved %ld, %ld without)",
                      workers, carried, want_carried, big_solved, want_solved);
        task_pool_destroy(p);
    }
    wd = with_backwards(&b);
    CHECK(big_run(&wd, &carried) == want);
    CHECK(carried == want_carried && big_solved == want_solved);
    CHECK(b.bad == 0);
    CHECK(b.calls > BIG_STEPS); /* several stages a step were handed over */
    CHECK(b.ranges > 4 * b.calls); /* and cut: at least the narrowphase's ~22 blocks */
    {
        deferred d;
        memset(&d, 0, sizeof d);
        wd = ga2d_default_world_def();
        wd.worker_count = 3;
        wd.enqueue_task = deferred_enqueue;
        wd.finish_task = deferred_finish;
        wd.user_task_context = &d;
        CHECK(big_run(&wd, &carried) == want);
        CHECK(carried == want_carried && big_solved == want_solved);
        CHECK(d.bad == 0 && d.pending == 0);
        CHECK(d.jobs > BIG_STEPS); /* several stages a step were handed over */
    }
}

/* The def's task fields: a negative or too large worker count, or one of
   enqueue and finish without the other, is refused (validate and create);
   a task system that calls the world from inside a stage gets LOCKED and
   the step goes on (the same bits). */
static void task_fields_checked(void)
{
    ga2d_world_def wd = ga2d_default_world_def();
    backwards b;
    long carried;
    uint64_t want;
    wd.worker_count = -1;
    CHECK_RESULT(ga2d_world_def_validate(&wd), GA2D_ERR_INVALID_ARGUMENT);
    CHECK(ga2d_world_create(&wd) == NULL);
    wd.worker_count = GA2D_MAX_WORKERS + 1;
    CHECK_RESULT(ga2d_world_def_validate(&wd), GA2D_ERR_INVALID_ARGUMENT);
    wd.worker_count = GA2D_MAX_WORKERS;
    CHECK_RESULT(ga2d_world_def_validate(&wd), GA2D_OK);
    wd.enqueue_task = backwards_enqueue;
    CHECK_RESULT(ga2d_world_def_validate(&wd), GA2D_ERR_INVALID_ARGUMENT);
    CHECK(ga2d_world_create(&wd) == NULL);
    wd.enqueue_task = NULL;
    wd.finish_task = backwards_finish;
    CHECK_RESULT(ga2d_world_def_validate(&wd), GA2D_ERR_INVALID_ARGUMENT);
    wd.enqueue_task = backwards_enqueue;
    CHECK_RESULT(ga2d_world_def_validate(&wd), GA2D_OK);
    /* the world called from its task system */
    wd = ga2d_default_world_def();
    want = big_run(&wd, &carried);
    wd = with_backwards(&b);
    b.probe = 1;
    b.probed = GA2D_ERR_LOCKED;
    {
        ga2d_world *w = ga2d_world_create(&wd);
        ga2d_body_def d = ga2d_default_body_def();
        int i;
        CHECK(w != NULL);
        if (!w) return;
        b.world = w;
        d.type = GA2D_BODY_DYNAMIC;
        d.polygon = ga2d_polygon_box((ga2d_real)0.5, (ga2d_real)0.5);
        for (i = 0; i < 400; ++i) { /* enough bodies that the step hands stages over */
            d.position = ga2d_vec_make((ga2d_real)(i % 20), (ga2d_real)(i / 20));
            ga2d_body_create(w, &d);
        }
        CHECK_RESULT(ga2d_world_step(w, (ga2d_real)1 / 60), GA2D_OK);
        CHECK(b.calls > 0);
        CHECK_RESULT(b.probed, GA2D_ERR_LOCKED);
        CHECK(ga2d_world_body_count(w) == 400);
        ga2d_world_destroy(w);
    }
    b.probe = 0;
    b.world = NULL;
    CHECK(big_run(&wd, &carried) == want);
}

/* ----------------------------------------------- bare hinges in lanes */
/* The hinge net of determinism_scene.h (dhinge_run) both ways, bare
   hinges in lanes and the same joints one by one: the same bits, for each
   solver kind, with warm starting off too, on no task system and on a pool
   of 3.  A net of 24 x 24 has colours of over a thousand joints, handed to
   the workers in blocks (every build of determinism.c checks a smaller
   one, in every lane width). */
#define HINGE_NET 24
static void hinge_lanes_same_bits(void)
{
    static const ga2d_solver solvers[] = {GA2D_SOLVER_SOFT_STEP, GA2D_SOLVER_PGS_BAUMGARTE, GA2D_SOLVER_PGS_NGS};
    task_pool *p = task_pool_create(3);
    int s, warm, pooled;
    CHECK(p != NULL);
    for (s = 0; s < 3; ++s)
        for (warm = 0; warm < 2; ++warm)
            for (pooled = 0; pooled < 2; ++pooled) {
                ga2d_world_def wd = pooled && p ? with_pool(p) : ga2d_default_world_def();
                uint64_t lanes, one_by_one;
                int in_lanes, none;
                wd.solver = solvers[s];
                wd.enable_warm_starting = warm;
                lanes = dhinge_run(wd, HINGE_NET, 1, &in_lanes);
                one_by_one = dhinge_run(wd, HINGE_NET, 0, &none);
                CHECK(lanes != 0);
                /* four of five joints are bare: most of them fill whole groups */
                CHECK(in_lanes > DHINGE_JOINTS(HINGE_NET) / 2);
                CHECK(none == 0);
                if (lanes != one_by_one)
                    test_fail(__FILE__, __LINE__, "solver %d, warm starting %d, pooled %d: %016llx in lanes, %016llx one by one", s,
                              warm, pooled, (unsigned long long)lanes, (unsigned long long)one_by_one);
            }
    if (p) task_pool_destroy(p);
}

/* ------------------------------------------------ hit events on a team */
/* The solver's passes run on a team of the workers, and the member that
   finishes a pass keeps each point's peak impulse (what a hit event is
   made of) before the others go on.  HIT_BOXES boxes dropped side by side
   onto one ground, all reporting hits: their ground contacts are one
   colour of HIT_BOXES / 4 groups (float lanes), past GA2D__COLOUR_MIN, so
   shared.  Each step's hit events, every field, must be those of the
   world with no task system: on a pool of 2 and 3, on the backwards
   system (the members one after the other) and on a pool of 2 threads
   told of 4 workers (two members a thread). */
#define HIT_BOXES 480
#define HIT_STEPS 90
typedef struct hit_log {
    int steps_with_hits, total;
    uint64_t hash;
} hit_log;

static hit_log hit_run(ga2d_world_def wd)
{
    hit_log log = {0, 0, 14695981039346656037ull};
    ga2d_world *w = ga2d_world_create(&wd);
    ga2d_body_def d = ga2d_default_body_def();
    ga2d_shape_def sd = ga2d_default_shape_def();
    ga2d_polygon box = ga2d_polygon_box((ga2d_real)0.4, (ga2d_real)0.4);
    int i, step, ok = w != NULL;
    if (!ok) return log;
    d.polygon = ga2d_polygon_box(HIT_BOXES, (ga2d_real)0.5); /* under every box */
    d.position = ga2d_vec_make(0, (ga2d_real)-0.5);
    ga2d_body_create(w, &d);
    d.polygon.count = 0;
    d.type = GA2D_BODY_DYNAMIC;
    sd.enable_hit_events = 1;
    for (i = 0; i < HIT_BOXES; ++i) { /* 1 m apart, from 0.5 to 2 m up: they land in different steps */
        ga2d_body_id id;
        d.position = ga2d_vec_make((ga2d_real)(i - HIT_BOXES / 2), (ga2d_real)(1 + 0.5 * (i % 4)));
        id = ga2d_body_create(w, &d);
        ok = ok && !ga2d_shape_id_is_null(ga2d_shape_create_polygon(w, id, &sd, &box));
    }
    for (step = 0; ok && step < HIT_STEPS; ++step) {
        ga2d_contact_events ev;
        ok = ga2d_world_step(w, (ga2d_real)1 / 60) == GA2D_OK;
        ev = ga2d_world_contact_events(w);
        log.steps_with_hits += ev.hit_count > 0;
        log.total += ev.hit_count;
        for (i = 0; i < ev.hit_count; ++i) {
            const ga2d_contact_hit_event *h = &ev.hit[i];
            /* the ids' slots (their generations carry each world's own tag) */
            log.hash = dscene_fnv(log.hash, &h->shape_a.index1, sizeof h->shape_a.index1);
            log.hash = dscene_fnv(log.hash, &h->shape_b.index1, sizeof h->shape_b.index1);
            log.hash = dscene_fnv(log.hash, &h->point, sizeof h->point);
            log.hash = dscene_fnv(log.hash, &h->normal, sizeof h->normal);
            log.hash = dscene_fnv(log.hash, &h->approach_speed, sizeof h->approach_speed);
        }
    }
    ga2d_world_destroy(w);
    if (!ok) log.total = -1;
    return log;
}

static void hit_events_on_a_team(void)
{
    hit_log want = hit_run(ga2d_default_world_def()), got;
    backwards b;
    int workers;
    /* every box lands once: a hit each, in at least the 4 steps of the 4 heights */
    CHECK(want.total >= HIT_BOXES);
    CHECK(want.steps_with_hits >= 4);
    for (workers = 2; workers <= 3; ++workers) {
        task_pool *p = task_pool_create(workers);
        CHECK(p != NULL);
        if (!p) continue;
        got = hit_run(with_pool(p));
        if (got.total != want.total || got.hash != want.hash)
            test_fail(__FILE__, __LINE__, "%d workers: %d hits (hash %016llx), %d without (%016llx)", workers, got.total,
                      (unsigned long long)got.hash, want.total, (unsigned long long)want.hash);
        task_pool_destroy(p);
    }
    got = hit_run(with_backwards(&b));
    CHECK(got.total == want.total && got.hash == want.hash);
    CHECK(b.bad == 0);
    {
        task_pool *p = task_pool_create(2);
        ga2d_world_def wd;
        CHECK(p != NULL);
        if (!p) return;
        wd = with_pool(p);
        wd.worker_count = 4;
        got = hit_run(wd);
        if (got.total != want.total || got.hash != want.hash) test_fail(__FILE__, __LINE__, "2 threads as 4 workers: %d hits %d steps (hash %016llx), %d %d without (%016llx)", got.total, got.steps_with_hits, (unsigned long long)got.hash, want.total, want.steps_with_hits, (unsigned long long)want.hash);
        task_pool_destroy(p);
    }
}

/* ------------------------------------------------- the pool on its own */
/* Every item of every job is done exactly once, by the time finish
   returns: jobs of 2 to 38 items back to back, so a worker late for one
   job meets the next one being posted (the pool once let such a worker
   claim the next job's items with the last one's count, doing some
   twice). */
#define POOL_JOBS 20000
#define POOL_MAX_ITEMS 38
typedef struct pool_job { int items[POOL_MAX_ITEMS]; } pool_job;

static void pool_count(int start, int end, int worker, void *context)
{
    pool_job *j = (pool_job *)context;
    int i;
    (void)worker;
    for (i = start; i < end; ++i) ++j->items[i];
}

static void pool_every_item_once(void)
{
    int workers;
    for (workers = 2; workers <= 4; ++workers) {
        task_pool *p = task_pool_create(workers);
        pool_job job;
        int k, i, bad = 0;
        CHECK(p != NULL);
        if (!p) continue;
        for (k = 0; k < POOL_JOBS; ++k) {
            int n = 2 + k % (POOL_MAX_ITEMS - 1);
            void *handle;
            memset(&job, 0, sizeof job);
            handle = task_pool_enqueue(pool_count, n, 1, &job, p);
            if (handle) task_pool_finish(handle, p);
            for (i = 0; i < n; ++i) bad += job.items[i] != 1;
        }
        if (bad) test_fail(__FILE__, __LINE__, "%d workers: %d items not done exactly once", workers, bad);
        task_pool_destroy(p);
    }
}

void suite_threads(void)
{
    test_run("threads: the example pool does every item of every job once", pool_every_item_once);
    test_run("threads: the determinism scene's hash with 1-4 workers, backwards and inline", any_worker_count_same_bits);
    test_run("threads: a big mixed scene's bits and counters with every task system", big_scene_same_bits);
    test_run("threads: task fields checked; the world refuses its task system", task_fields_checked);
    test_run("threads: hit events on the workers' team are those without workers", hit_events_on_a_team);
    test_run("threads: bare hinges in lanes give the one-by-one bits (every solver, pooled, contained)", hinge_lanes_same_bits);
}
