/* Failure injection (issue 8): an allocator that fails its k-th
   allocation, run through one scenario for every k the scenario reaches.

   The scenario: create a world; add a ground, a pyramid and polygons
   falling onto it from staggered heights (so that contacts, pairs,
   constraints and events keep growing during the steps, and their arrays
   with them); step; destroy some bodies; step; switch to RK4 (its
   per-body scratch is allocated); add bodies (more scratch); step;
   destroy the world.  A dry run counts the allocations K and notes which
   call made each; then the scenario runs K more times, allocation k
   failing, and at every call:
     - an allocation that failed inside a call is reported by it
       (GA2D_ERR_OUT_OF_MEMORY, the null id, or NULL), and a call whose
       allocations all succeeded reports success;
     - where the API promises it, the failed call changed nothing:
       ga2d_body_create ("every allocation first") leaves every body's
       state as the getters report it and the counters bit-identical,
       ga2d_world_set_integrator leaves the integrator (seen in the next
       step's force evaluations: 1 per substep, 4 for RK4);
     - the scenario goes on with the allocator working again (the failed
       call is retried and succeeds) and every step after leaves every
       body finite;
     - after ga2d_world_destroy the allocator got every byte back (bytes
       allocated minus bytes freed is 0, each free with the size of its
       allocation, no double free), whatever failed.
   LeakSanitizer in the sanitizer builds checks the same from outside. */
#include "test.h"

/* --------------------------------------------------------------- allocator */
/* Each block carries its size in a header, so a free with another size,
   or of something never allocated, is caught. */
#define FI_MAGIC 0x46494e4au
#define FI_HEADER 16

enum { PH_NONE, PH_WORLD, PH_CREATE, PH_FIRST_STEP, PH_STEP, PH_INTEGRATOR, PH_COUNT };

typedef struct fi_alloc {
    long attempts, fail_at, failures;
    long live_blocks;
    size_t live_bytes;
    int bad_free;
    int phase;              /* the call being made */
    int failed_phase;       /* the call whose allocation failed */
    unsigned char *phases;  /* dry run: the phase of each attempt */
    long phase_cap;
} fi_alloc;

static void *fi_alloc_fn(size_t size, void *ctx)
{
    fi_alloc *a = (fi_alloc *)ctx;
    unsigned char *p;
    unsigned magic = FI_MAGIC;
    ++a->attempts;
    if (a->phases) {
        if (a->attempts > a->phase_cap) {
            long cap = a->phase_cap ? 2 * a->phase_cap : 256;
            unsigned char *q = (unsigned char *)realloc(a->phases, (size_t)cap);
            if (!q) abort();
            a->phases = q;
            a->phase_cap = cap;
        }
        a->phases[a->attempts - 1] = (unsigned char)a->phase;
    }
    if (a->attempts == a->fail_at) {
        ++a->failures;
        a->failed_phase = a->phase;
        return NULL;
    }
    p = (unsigned char *)malloc(size + FI_HEADER);
    if (!p) abort();
    memcpy(p, &size, sizeof size);
    memcpy(p + sizeof size, &magic, sizeof magic);
    ++a->live_blocks;
    a->live_bytes += size;
    return p + FI_HEADER;
}

static void fi_free_fn(void *ptr, size_t size, void *ctx)
{
    fi_alloc *a = (fi_alloc *)ctx;
    unsigned char *p = (unsigned char *)ptr - FI_HEADER;
    size_t was;
    unsigned magic;
    memcpy(&was, p, sizeof was);
    memcpy(&magic, p + sizeof was, sizeof magic);
    if (magic != FI_MAGIC || was != size || a->live_blocks <= 0) {
        ++a->bad_free; /* not ours, freed twice, or the wrong size */
        return;
    }
    memset(p + sizeof was, 0, sizeof magic); /* a second free is caught */
    --a->live_blocks;
    a->live_bytes -= size;
    free(p);
}

/* ------------------------------------------------------------ the scenario */
#define PYR_BASE 4
#define FALLING 8
#define MAX_IDS 40
#define SUBSTEPS 4

typedef struct scene {
    fi_alloc *a;
    ga2d_world *w;
    ga2d_body_id ids[MAX_IDS];
    int n;
    int evaluations; /* force callback calls since the counter was reset */
    int bad_results; /* calls that reported a failure that did not happen, or hid one */
    int not_finite;  /* steps after which some body was not finite */
    int changed;     /* refused calls that changed the world */
    int retried;     /* failed calls retried */
} scene;

static void count_evaluations(ga2d_world *w, void *ctx)
{
    (void)w;
    ++((scene *)ctx)->evaluations;
}

/* Everything the getters say about every body, and the counters. */
typedef struct body_state {
    ga2d_vec position, center, velocity;
    ga2d_rotor q;
    ga2d_real w;
    ga2d_mass mass;
    int awake, type, valid;
} body_state;

typedef struct world_state {
    body_state bodies[MAX_IDS];
    int body_count, moving, pairs, touching;
} world_state;

static void take(const scene *s, world_state *o)
{
    ga2d_world_counters c = ga2d_world_get_counters(s->w);
    int i;
    memset(o, 0, sizeof *o);
    for (i = 0; i < s->n; ++i) {
        ga2d_body_id id = s->ids[i];
        body_state *b = &o->bodies[i];
        b->position = ga2d_body_position(s->w, id);
        b->center = ga2d_body_center(s->w, id);
        b->velocity = ga2d_body_velocity(s->w, id);
        b->q = ga2d_body_rotor(s->w, id);
        b->w = ga2d_body_angular_velocity(s->w, id);
        b->mass = ga2d_body_mass_data(s->w, id);
        b->awake = ga2d_body_is_awake(s->w, id);
        b->type = (int)ga2d_body_get_type(s->w, id);
        b->valid = ga2d_body_is_valid(s->w, id);
    }
    o->body_count = c.body_count;
    o->moving = c.moving_body_count;
    o->pairs = c.pair_count;
    o->touching = c.touching_count;
}

static int finite_real(ga2d_real x) { return x - x == 0; }

static int all_finite(const scene *s)
{
    int i, ok = 1;
    for (i = 0; i < s->n; ++i) {
        ga2d_body_id id = s->ids[i];
        ga2d_vec c = ga2d_body_center(s->w, id), v = ga2d_body_velocity(s->w, id);
        ga2d_rotor q = ga2d_body_rotor(s->w, id);
        ok &= finite_real(c.x) && finite_real(c.y) && finite_real(v.x) && finite_real(v.y) && finite_real(q.c) &&
              finite_real(q.s) && finite_real(ga2d_body_angular_velocity(s->w, id));
    }
    return ok;
}

/* A body create, retried once if an allocation failed: the failure must
   give the null id and leave the world exactly as it was. */
static void create(scene *s, const ga2d_body_def *d)
{
    world_state before, after;
    long failures = s->a->failures;
    ga2d_body_id id;
    take(s, &before);
    s->a->phase = PH_CREATE;
    id = ga2d_body_create(s->w, d);
    if (s->a->failures != failures) {
        s->bad_results += !ga2d_body_id_is_null(id);
        take(s, &after);
        s->changed += memcmp(&before, &after, sizeof before) != 0;
        ++s->retried;
        failures = s->a->failures;
        id = ga2d_body_create(s->w, d);
        s->bad_results += s->a->failures != failures; /* only one allocation fails */
    }
    s->bad_results += ga2d_body_id_is_null(id);
    if (s->n < MAX_IDS) s->ids[s->n++] = id;
    s->a->phase = PH_NONE;
}

static ga2d_body_def dynamic_def(double x, double y, ga2d_polygon p)
{
    ga2d_body_def d = ga2d_default_body_def();
    d.type = GA2D_BODY_DYNAMIC;
    d.position = ga2d_vec_make((ga2d_real)x, (ga2d_real)y);
    d.polygon = p;
    return d;
}

/* One step: OUT_OF_MEMORY exactly when an allocation failed in it; every
   body finite after it, whatever it reported. */
static void step(scene *s, int phase)
{
    long failures = s->a->failures;
    ga2d_result r;
    s->a->phase = phase;
    r = ga2d_world_step(s->w, (ga2d_real)(1.0 / 60));
    s->a->phase = PH_NONE;
    s->bad_results += (s->a->failures != failures) ? r != GA2D_ERR_OUT_OF_MEMORY : r != GA2D_OK;
    s->not_finite += !all_finite(s);
}

static void steps(scene *s, int n)
{
    int i;
    for (i = 0; i < n; ++i) step(s, PH_STEP);
}

/* The whole scenario with allocator `a`; returns 1 if every call behaved. */
static int run_scenario(fi_alloc *a, scene *s)
{
    ga2d_world_def wd = ga2d_default_world_def();
    ga2d_body_def d;
    int i, j;
    memset(s, 0, sizeof *s);
    s->a = a;
    wd.allocator.alloc = fi_alloc_fn;
    wd.allocator.free = fi_free_fn;
    wd.allocator.ctx = a;
    wd.substeps = SUBSTEPS;
    wd.enable_sleep = 0; /* contacts stay in the step, growing as bodies land */
    wd.force_callback = count_evaluations;
    wd.force_context = s;

    a->phase = PH_WORLD;
    s->w = ga2d_world_create(&wd);
    if (!s->w) {
        /* refused only because the allocation failed, with nothing kept */
        s->bad_results += a->failures != 1 || a->live_bytes != 0 || a->live_blocks != 0;
        ++s->retried;
        s->w = ga2d_world_create(&wd);
        if (!s->w) return 0;
    }
    a->phase = PH_NONE;

    /* the ground, a pyramid resting on it, and polygons above it */
    d = ga2d_default_body_def();
    d.position = ga2d_vec_make(0, -1);
    d.polygon = ga2d_polygon_box(20, 1);
    create(s, &d);
    for (i = 0; i < PYR_BASE; ++i)
        for (j = i; j < PYR_BASE; ++j) {
            d = dynamic_def((i + 1) * 0.5 + (j - i) - PYR_BASE / 2.0, 0.5 + i, ga2d_polygon_box((ga2d_real)0.5, (ga2d_real)0.5));
            create(s, &d);
        }
    for (i = 0; i < FALLING; ++i) {
        ga2d_polygon p = i % 3 == 0 ? ga2d_polygon_regular(3 + i % 6, (ga2d_real)0.45)
                                    : ga2d_polygon_box((ga2d_real)(0.3 + 0.05 * i), (ga2d_real)0.3);
        d = dynamic_def(-3.0 + 0.8 * i, PYR_BASE + 1.5 + 0.7 * i, p);
        create(s, &d);
    }

    /* the first step finds the pyramid's pairs; later steps add the
       falling bodies' contacts as they land (0.7 m apart in height: one
       lands every ~5 steps over the first second) */
    step(s, PH_FIRST_STEP);
    steps(s, 79);

    /* destroy some: the top of the pyramid and two that fell */
    for (i = s->n - 1; i >= s->n - 3; --i) ga2d_body_destroy(s->w, s->ids[i]);
    ga2d_body_destroy(s->w, s->ids[1 + PYR_BASE * (PYR_BASE + 1) / 2 - 1]);
    steps(s, 30);

    /* RK4 keeps per-body scratch: switching allocates it.  A refusal
       leaves symplectic Euler, whose step evaluates the field once per
       substep; RK4 evaluates it four times. */
    {
        long failures = a->failures;
        ga2d_result r;
        a->phase = PH_INTEGRATOR;
        r = ga2d_world_set_integrator(s->w, GA2D_INTEGRATOR_RK4);
        a->phase = PH_NONE;
        if (a->failures != failures) {
            s->bad_results += r != GA2D_ERR_OUT_OF_MEMORY;
            s->evaluations = 0;
            step(s, PH_STEP);
            s->changed += s->evaluations != SUBSTEPS;
            ++s->retried;
            r = ga2d_world_set_integrator(s->w, GA2D_INTEGRATOR_RK4);
        }
        s->bad_results += r != GA2D_OK;
        s->evaluations = 0;
        step(s, PH_STEP);
        s->bad_results += s->evaluations != 4 * SUBSTEPS;
    }
    /* bodies made under RK4 grow its scratch too */
    for (i = 0; i < 4; ++i) {
        d = dynamic_def(-1.5 + i, PYR_BASE + 3.0, ga2d_polygon_box((ga2d_real)0.25, (ga2d_real)0.25));
        create(s, &d);
    }
    steps(s, 20);
    {
        /* every body made is there, less the four destroyed */
        int live = 0;
        for (i = 0; i < s->n; ++i) live += ga2d_body_is_valid(s->w, s->ids[i]);
        s->bad_results += ga2d_world_get_counters(s->w).body_count != live || live != s->n - 4;
    }
    ga2d_world_destroy(s->w);
    s->w = NULL;
    return 1;
}

static void inject_every_allocation(void)
{
    fi_alloc dry;
    scene s;
    long k, K, in_growing_steps = 0, failed_runs = 0, leaked_runs = 0, missed = 0;
    long phase_counts[PH_COUNT];
    memset(&dry, 0, sizeof dry);
    memset(phase_counts, 0, sizeof phase_counts);
    dry.phases = (unsigned char *)malloc(256);
    dry.phase_cap = 256;
    CHECK(dry.phases != NULL);
    if (!dry.phases) return;
    /* the dry run: nothing fails, everything succeeds, nothing leaks */
    CHECK(run_scenario(&dry, &s));
    CHECK(s.bad_results == 0 && s.not_finite == 0 && s.changed == 0 && s.retried == 0);
    CHECK(dry.live_bytes == 0 && dry.live_blocks == 0 && dry.bad_free == 0);
    K = dry.attempts;
    for (k = 0; k < K; ++k) ++phase_counts[dry.phases[k]];
    in_growing_steps = phase_counts[PH_STEP];
    /* the scenario reaches every kind of allocation: the world, bodies,
       the first step's pairs, steps after it (contacts growing as bodies
       land) and the integrator's scratch */
    CHECK(phase_counts[PH_WORLD] >= 1 && phase_counts[PH_CREATE] >= 1 && phase_counts[PH_FIRST_STEP] >= 1);
    CHECK(in_growing_steps >= 1 && phase_counts[PH_INTEGRATOR] >= 1);
    for (k = 1; k <= K; ++k) {
        fi_alloc a;
        memset(&a, 0, sizeof a);
        a.fail_at = k;
        if (!run_scenario(&a, &s)) {
            ++failed_runs;
            continue;
        }
        /* allocation k failed, in the call the dry run made it in (the
           runs are identical up to it), and that call reported it */
        missed += a.failures != 1 || a.failed_phase != dry.phases[k - 1] ||
                  s.retried != (a.failed_phase == PH_WORLD || a.failed_phase == PH_CREATE || a.failed_phase == PH_INTEGRATOR);
        failed_runs += s.bad_results != 0 || s.not_finite != 0 || s.changed != 0;
        leaked_runs += a.live_bytes != 0 || a.live_blocks != 0 || a.bad_free != 0;
        if (s.bad_results || s.not_finite || s.changed || a.live_bytes || a.bad_free)
            printf("  failinject: k = %ld (phase %d): bad results %d, not finite %d, changed %d, live bytes %lu, bad frees %d\n",
                   k, dry.phases[k - 1], s.bad_results, s.not_finite, s.changed, (unsigned long)a.live_bytes, a.bad_free);
    }
    CHECK(failed_runs == 0);
    CHECK(leaked_runs == 0);
    CHECK(missed == 0);
    {
        const char *v = getenv("GA2D_TEST_VERBOSE");
        if (v && v[0])
            printf("failinject: %ld allocations (world %ld, body create %ld, first step %ld, later steps %ld, integrator %ld), "
                   "each failed once: all reported, world unchanged where promised, steps finite, 0 bytes leaked\n",
                   K, phase_counts[PH_WORLD], phase_counts[PH_CREATE], phase_counts[PH_FIRST_STEP], phase_counts[PH_STEP],
                   phase_counts[PH_INTEGRATOR]);
    }
    free(dry.phases);
}

void suite_failinject(void)
{
    test_run("failinject: every allocation of a growing scene fails once, reported, no leak", inject_every_allocation);
}
