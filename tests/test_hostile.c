/* Hostile input: regression tests for what user code and extreme input
   could do to a world before 0.8.1 (see the header's ERRORS section,
   "Calls from inside the library's callbacks" and "Bounds").

   - Debug-draw callbacks find the world locked: every change is refused,
     the getters read the live world, and nothing changes.
   - ga2d_world_destroy from user code (force callback, draw callback,
     allocator alloc hook, free hook of a destroy) is deferred to the end
     of the library call: no use after free, no leak, no double free.
   - Allocator hooks that call back into the world are refused.
   - Fast small bodies do not tunnel through thin walls.
   - Bodies created overlapping do not fall asleep embedded.
   - A thin, gently curved polygon comes to rest on its curved side.
   - Ids of one world are refused by another; the world-free collider
     refuses bad rotors and polygons; coordinates, steps and gravity have
     bounds (GA2D_ERR_TOO_LARGE).
   - counters.speed_caps tells a program that its scene is blowing up.

   Every bound is derived in the comment above its test; with
   GA2D_TEST_VERBOSE set every measured figure is printed next to it. */
#include "test.h"

static int verbose(void)
{
    const char *v = getenv("GA2D_TEST_VERBOSE");
    return v != NULL && v[0] != '\0';
}

static ga2d_vec vec(double x, double y) { return ga2d_vec_make((ga2d_real)x, (ga2d_real)y); }
static int vec_same(ga2d_vec a, ga2d_vec b) { return a.x == b.x && a.y == b.y; }

/* Default world without gravity. */
static ga2d_world *weightless_world(void)
{
    ga2d_world_def wd = ga2d_default_world_def();
    wd.gravity = vec(0, 0);
    return ga2d_world_create(&wd);
}

static ga2d_body_def box_def(ga2d_body_type type, double x, double y, double hx, double hy)
{
    ga2d_body_def d = ga2d_default_body_def();
    d.type = type;
    d.position = vec(x, y);
    d.polygon = ga2d_polygon_box((ga2d_real)hx, (ga2d_real)hy);
    return d;
}

/* The whole world as bytes (a snapshot), malloc'd; NULL on failure. */
static unsigned char *world_bytes(const ga2d_world *w, size_t *size)
{
    unsigned char *buf;
    *size = ga2d_world_snapshot_size(w);
    buf = (unsigned char *)malloc(*size ? *size : 1);
    if (!buf) return NULL;
    if (ga2d_world_snapshot_save(w, buf, *size) != GA2D_OK) {
        free(buf);
        return NULL;
    }
    return buf;
}

static int same_bytes(const unsigned char *a, size_t na, const unsigned char *b, size_t nb)
{
    return a && b && na == nb && memcmp(a, b, na) == 0;
}

/* ------------------------------------------------------------- allocator */
/* A counting allocator that remembers every live block and its size (so
   a double free, or a free of the wrong size, is seen), and whose hooks
   can be told to call back into the world they serve. */
#define HA_MAX_BLOCKS 512

typedef struct hook_alloc {
    void *block[HA_MAX_BLOCKS];
    size_t size[HA_MAX_BLOCKS];
    int nblocks, overflow;
    long allocs, frees, bad_frees;
    size_t live_bytes;
    /* what the hooks do to w */
    ga2d_world *w;
    int destroy_on_alloc; /* armed: the next alloc calls ga2d_world_destroy(w) */
    int reenter_on_alloc; /* every alloc tries to change w */
    int destroy_on_free;  /* every free calls ga2d_world_destroy(w) first */
    int read_on_free;     /* every free reads w through the getters first */
    ga2d_body_id probe;   /* a body of w for the hooks to use */
    int fired;            /* hook calls that did something */
    int wrong;            /* calls from a hook that were not refused */
    int most_bodies_seen; /* read_on_free: the largest body_count read */
    int valid_seen;       /* read_on_free: reads that found probe valid */
} hook_alloc;

static void ha_init(hook_alloc *a)
{
    memset(a, 0, sizeof *a);
    a->most_bodies_seen = -1;
}

/* From inside an allocation: every change to the world is refused. */
static void ha_reenter(hook_alloc *a)
{
    ga2d_body_def d = box_def(GA2D_BODY_DYNAMIC, 50, 50, 0.5, 0.5);
    ga2d_vec g = ga2d_world_gravity(a->w);
    ++a->fired;
    a->wrong += !ga2d_body_id_is_null(ga2d_body_create(a->w, &d));
    a->wrong += ga2d_world_step(a->w, (ga2d_real)(1.0 / 60)) != GA2D_ERR_LOCKED;
    a->wrong += ga2d_body_destroy(a->w, a->probe) != GA2D_ERR_LOCKED;
    a->wrong += ga2d_world_set_gravity(a->w, vec(0, 3)) != GA2D_ERR_LOCKED;
    a->wrong += !vec_same(ga2d_world_gravity(a->w), g);
}

static void *ha_alloc(size_t size, void *ctx)
{
    hook_alloc *a = (hook_alloc *)ctx;
    void *p;
    if (a->w && a->destroy_on_alloc) {
        a->destroy_on_alloc = 0;
        ++a->fired;
        ga2d_world_destroy(a->w);
    }
    if (a->w && a->reenter_on_alloc) ha_reenter(a);
    if (a->nblocks == HA_MAX_BLOCKS) {
        a->overflow = 1;
        return NULL;
    }
    p = malloc(size ? size : 1);
    if (!p) return NULL;
    a->block[a->nblocks] = p;
    a->size[a->nblocks] = size;
    ++a->nblocks;
    ++a->allocs;
    a->live_bytes += size;
    return p;
}

static void ha_free(void *ptr, size_t size, void *ctx)
{
    hook_alloc *a = (hook_alloc *)ctx;
    int i;
    /* the hooks run before the block goes: the last block freed by a
       destroy is the world itself, still readable until then */
    if (a->w && a->destroy_on_free) {
        ++a->fired;
        ga2d_world_destroy(a->w);
    }
    if (a->w && a->read_on_free) {
        int n = ga2d_world_get_counters(a->w).body_count;
        ++a->fired;
        if (n > a->most_bodies_seen) a->most_bodies_seen = n;
        a->valid_seen += ga2d_body_is_valid(a->w, a->probe) != 0;
        a->wrong += !vec_same(ga2d_body_position(a->w, a->probe), vec(0, 0));
        a->wrong += ga2d_world_get_contacts(a->w, NULL, 0) != 0;
    }
    for (i = 0; i < a->nblocks; ++i)
        if (a->block[i] == ptr) break;
    if (i == a->nblocks || a->size[i] != size) {
        ++a->bad_frees; /* freed twice, not ours, or the wrong size */
        return;
    }
    a->live_bytes -= size;
    a->block[i] = a->block[--a->nblocks];
    a->size[i] = a->size[a->nblocks];
    ++a->frees;
    free(ptr);
}

static ga2d_world_def ha_world_def(hook_alloc *a)
{
    ga2d_world_def d = ga2d_default_world_def();
    d.allocator.alloc = ha_alloc;
    d.allocator.free = ha_free;
    d.allocator.ctx = a;
    return d;
}

/* every block given back exactly once, with its size */
static void ha_check_clean(const hook_alloc *a)
{
    CHECK(a->live_bytes == 0);
    CHECK(a->nblocks == 0);
    CHECK(a->allocs == a->frees);
    CHECK(a->bad_frees == 0);
    CHECK(a->overflow == 0);
}

/* A ground and a stack of two boxes, stepped until they touch. */
static void small_scene(ga2d_world *w, ga2d_body_id ids[3])
{
    ga2d_body_def g = box_def(GA2D_BODY_STATIC, 0, -0.5, 5, 0.5);
    ga2d_body_def b1 = box_def(GA2D_BODY_DYNAMIC, 0, 0.5, 0.5, 0.5);
    ga2d_body_def b2 = box_def(GA2D_BODY_DYNAMIC, 0.1, 1.5, 0.5, 0.5);
    int i;
    ids[0] = ga2d_body_create(w, &g);
    ids[1] = ga2d_body_create(w, &b1);
    ids[2] = ga2d_body_create(w, &b2);
    for (i = 0; i < 3; ++i) CHECK(!ga2d_body_id_is_null(ids[i]));
    for (i = 0; i < 10; ++i) CHECK_RESULT(ga2d_world_step(w, (ga2d_real)(1.0 / 60)), GA2D_OK);
    CHECK(ga2d_world_get_contacts(w, NULL, 0) > 0);
}

/* ================================================= 1. draw callbacks lock */
/* Old bug: ga2d_world_draw took a const world but did not lock it, so a
   polygon callback could create or destroy bodies (moving the arrays the
   draw was reading), step, load a snapshot, or draw again.  Now every
   change from a draw callback is refused with GA2D_ERR_LOCKED (create
   returns the null id) and the getters read the live world.  The bounds
   are exact: every refused call must change nothing, so the body count and
   the snapshot bytes are equal before and after, and a getter inside the
   callback returns the same bits as before the draw (and as the
   transform the callback was handed). */
typedef struct draw_probe {
    ga2d_world *w;
    ga2d_body_id ids[3];
    ga2d_vec pos[3], vel[3];
    const unsigned char *snap;
    size_t snap_size;
    unsigned char *scratch;
    const ga2d_debug_draw *draw;
    int polygons, aabbs, tries, wrong, live_ok;
} draw_probe;

static void probe_polygon(ga2d_body_id id, const ga2d_polygon *p, ga2d_transform x, uint32_t color, void *ctx)
{
    draw_probe *d = (draw_probe *)ctx;
    ga2d_world *w = d->w;
    ga2d_body_def bd = box_def(GA2D_BODY_DYNAMIC, 20, 20, 0.5, 0.5);
    int k = (int)id.index1 - 1;
    (void)p;
    (void)color;
    ++d->polygons;
    if (k < 0 || k >= 3 || !ga2d_body_id_equal(id, d->ids[k])) {
        ++d->wrong;
        return;
    }
    d->tries += 11;
    d->wrong += !ga2d_body_id_is_null(ga2d_body_create(w, &bd));
    d->wrong += ga2d_body_destroy(w, id) != GA2D_ERR_LOCKED;
    d->wrong += ga2d_body_set_velocity(w, id, vec(3, 0)) != GA2D_ERR_LOCKED;
    d->wrong += ga2d_body_apply_impulse(w, id, vec(1, 0), x.p) != GA2D_ERR_LOCKED;
    d->wrong += ga2d_body_apply_force_to_center(w, id, vec(1, 0)) != GA2D_ERR_LOCKED;
    d->wrong += ga2d_world_step(w, (ga2d_real)(1.0 / 60)) != GA2D_ERR_LOCKED;
    d->wrong += ga2d_world_snapshot_save(w, d->scratch, d->snap_size) != GA2D_ERR_LOCKED;
    d->wrong += ga2d_world_snapshot_load(w, d->snap, d->snap_size) != GA2D_ERR_LOCKED;
    d->wrong += ga2d_world_set_gravity(w, vec(0, 5)) != GA2D_ERR_LOCKED;
    d->wrong += ga2d_world_enable_sleep(w, 0) != GA2D_ERR_LOCKED;
    d->wrong += ga2d_world_draw(w, d->draw) != GA2D_ERR_LOCKED;
    /* the getters read the live world */
    d->live_ok += vec_same(ga2d_body_position(w, id), d->pos[k]) && vec_same(ga2d_body_position(w, id), x.p) &&
                  vec_same(ga2d_body_velocity(w, id), d->vel[k]) && ga2d_body_is_valid(w, id) &&
                  ga2d_world_get_counters(w).body_count == 3;
}

static void probe_aabb(ga2d_aabb box, uint32_t color, void *ctx)
{
    draw_probe *d = (draw_probe *)ctx;
    (void)box;
    (void)color;
    ++d->aabbs;
    ++d->tries;
    d->wrong += ga2d_world_step(d->w, (ga2d_real)(1.0 / 60)) != GA2D_ERR_LOCKED;
}

static void draw_callbacks_are_locked(void)
{
    ga2d_world *w = ga2d_world_create(NULL);
    ga2d_debug_draw dd = ga2d_default_debug_draw();
    draw_probe d;
    unsigned char *before, *after;
    size_t nb, na;
    int i;
    memset(&d, 0, sizeof d);
    CHECK(w != NULL);
    if (!w) return;
    small_scene(w, d.ids);
    d.w = w;
    for (i = 0; i < 3; ++i) {
        d.pos[i] = ga2d_body_position(w, d.ids[i]);
        d.vel[i] = ga2d_body_velocity(w, d.ids[i]);
    }
    before = world_bytes(w, &nb);
    d.snap = before;
    d.snap_size = nb;
    d.scratch = (unsigned char *)malloc(nb);
    dd.polygon = probe_polygon;
    dd.aabb = probe_aabb;
    dd.draw_aabbs = 1;
    dd.context = &d;
    d.draw = &dd;
    CHECK(before != NULL && d.scratch != NULL);
    if (before && d.scratch) {
        CHECK_RESULT(ga2d_world_draw(w, &dd), GA2D_OK);
        int same;
        after = world_bytes(w, &na);
        same = same_bytes(before, nb, after, na);
        CHECK(d.polygons == 3 && d.aabbs == 3);
        CHECK(d.wrong == 0);
        CHECK(d.live_ok == 3);
        CHECK(ga2d_world_get_counters(w).body_count == 3);
        CHECK(same);
        free(after);
        /* unlocked once the draw returns */
        CHECK_RESULT(ga2d_world_step(w, (ga2d_real)(1.0 / 60)), GA2D_OK);
        if (verbose())
            printf("  hostile: draw lock: %d calls from callbacks, %d not refused (bound 0), "
                   "%d/3 live reads (bound 3), snapshot bytes %s (bound equal)\n",
                   d.tries, d.wrong, d.live_ok, same ? "equal" : "DIFFER");
    }
    free(before);
    free(d.scratch);
    ga2d_world_destroy(w);
}

/* ======================================== 2. destroy from user code runs */
/* Old bug: ga2d_world_destroy from the force callback (or a draw
   callback, or an allocator hook) freed the world at once, and the step
   (draw, create) carried on in freed memory.  Now the destroy is
   deferred: the call under way finishes without calling back again,
   returns as usual, then frees the world.  Bounds, all exact: with 4
   substeps and symplectic Euler the field is evaluated once per substep,
   so 4 calls in a whole step; a destroy at the 2nd call leaves exactly 2;
   every block the counting allocator handed out comes back once (live
   bytes 0). */
typedef struct force_probe {
    int calls, destroy_at, destroyed, calls_after;
} force_probe;

static void destroying_field(ga2d_world *w, void *ctx)
{
    force_probe *p = (force_probe *)ctx;
    ++p->calls;
    if (p->destroyed) ++p->calls_after;
    if (p->calls == p->destroy_at) {
        p->destroyed = 1;
        ga2d_world_destroy(w);
    }
}

static void destroy_from_force_callback(void)
{
    hook_alloc a;
    force_probe p;
    ga2d_world_def wd;
    ga2d_world *w;
    ga2d_body_id ids[3];
    ha_init(&a);
    memset(&p, 0, sizeof p);
    wd = ha_world_def(&a);
    wd.substeps = 4;
    wd.integrator = GA2D_INTEGRATOR_SYMPLECTIC_EULER;
    wd.force_callback = destroying_field;
    wd.force_context = &p;
    w = ga2d_world_create(&wd);
    CHECK(w != NULL);
    if (!w) return;
    small_scene(w, ids);
    /* a normal step: one call per substep */
    p.calls = 0;
    CHECK_RESULT(ga2d_world_step(w, (ga2d_real)(1.0 / 60)), GA2D_OK);
    CHECK(p.calls == 4);
    CHECK(ga2d_world_get_counters(w).force_evaluations == 4);
    /* destroyed at the second call: the step returns, no third call */
    p.calls = 0;
    p.destroy_at = 2;
    CHECK_RESULT(ga2d_world_step(w, (ga2d_real)(1.0 / 60)), GA2D_OK);
    CHECK(p.destroyed == 1);
    CHECK(p.calls == 2 && p.calls_after == 0);
    ha_check_clean(&a);
    if (verbose())
        printf("  hostile: destroy in force callback: %d calls (bound 2), live bytes %lu (bound 0)\n", p.calls,
               (unsigned long)a.live_bytes);
}

typedef struct destroy_draw {
    ga2d_world *w;
    int calls, destroy_at, destroyed, calls_after;
} destroy_draw;

static void dd_count(destroy_draw *d)
{
    ++d->calls;
    if (d->destroyed) ++d->calls_after;
    if (d->calls == d->destroy_at) {
        d->destroyed = 1;
        ga2d_world_destroy(d->w);
    }
}

static void dd_polygon(ga2d_body_id id, const ga2d_polygon *p, ga2d_transform x, uint32_t color, void *ctx)
{
    (void)id;
    (void)p;
    (void)x;
    (void)color;
    dd_count((destroy_draw *)ctx);
}
static void dd_aabb(ga2d_aabb box, uint32_t color, void *ctx)
{
    (void)box;
    (void)color;
    dd_count((destroy_draw *)ctx);
}
static void dd_point(ga2d_vec p, ga2d_real size, uint32_t color, void *ctx)
{
    (void)p;
    (void)size;
    (void)color;
    dd_count((destroy_draw *)ctx);
}
static void dd_contact(ga2d_vec p, ga2d_vec n, ga2d_real sep, uint32_t color, void *ctx)
{
    (void)p;
    (void)n;
    (void)sep;
    (void)color;
    dd_count((destroy_draw *)ctx);
}

/* Per body the draw calls polygon, aabb, point (in that order): the 5th
   call is body 1's aabb, after which body 1's centre point is the only
   call of the same body left.  The header says drawing ends "at the next
   body", so at most that one call follows (bound 1); nothing of body 2 and
   no contact is drawn. */
static void destroy_from_draw_callback(void)
{
    hook_alloc a;
    ga2d_world_def wd;
    ga2d_world *w;
    ga2d_body_id ids[3];
    ga2d_debug_draw dd = ga2d_default_debug_draw();
    destroy_draw d;
    ha_init(&a);
    memset(&d, 0, sizeof d);
    wd = ha_world_def(&a);
    w = ga2d_world_create(&wd);
    CHECK(w != NULL);
    if (!w) return;
    small_scene(w, ids);
    d.w = w;
    d.destroy_at = 5; /* body 1's aabb */
    dd.polygon = dd_polygon;
    dd.aabb = dd_aabb;
    dd.point = dd_point;
    dd.contact = dd_contact;
    dd.draw_aabbs = dd.draw_centers = dd.draw_contacts = 1;
    dd.context = &d;
    CHECK_RESULT(ga2d_world_draw(w, &dd), GA2D_OK);
    CHECK(d.destroyed == 1);
    CHECK(d.calls_after <= 1);
    ha_check_clean(&a);
    if (verbose())
        printf("  hostile: destroy in draw callback: %d calls after it (bound 1), live bytes %lu (bound 0)\n",
               d.calls_after, (unsigned long)a.live_bytes);
}

/* The alloc hook during a body's creation destroys the world: the create
   returns, and then the world is gone (live bytes 0, each block freed
   once). */
static void destroy_from_alloc_hook(void)
{
    hook_alloc a;
    ga2d_world_def wd;
    ga2d_world *w;
    ga2d_body_def bd = box_def(GA2D_BODY_DYNAMIC, 0, 0, 0.5, 0.5);
    ha_init(&a);
    wd = ha_world_def(&a);
    w = ga2d_world_create(&wd);
    CHECK(w != NULL);
    if (!w) return;
    a.w = w;
    a.destroy_on_alloc = 1;
    (void)ga2d_body_create(w, &bd); /* the first body grows the arrays */
    CHECK(a.fired == 1);
    ha_check_clean(&a);
    if (verbose())
        printf("  hostile: destroy in alloc hook: live bytes %lu (bound 0), bad frees %ld (bound 0)\n",
               (unsigned long)a.live_bytes, a.bad_frees);
}

/* A free hook of ga2d_world_destroy that destroys the world again: the
   second destroy does nothing, every block is freed exactly once (a
   second free would be a block the allocator no longer holds: bad_frees). */
static void destroy_from_free_hook(void)
{
    hook_alloc a;
    ga2d_world_def wd;
    ga2d_world *w;
    ga2d_body_id ids[3];
    long allocs;
    ha_init(&a);
    wd = ha_world_def(&a);
    w = ga2d_world_create(&wd);
    CHECK(w != NULL);
    if (!w) return;
    small_scene(w, ids);
    allocs = a.allocs;
    a.w = w;
    a.destroy_on_free = 1;
    ga2d_world_destroy(w);
    CHECK(a.fired == (int)allocs); /* the hook ran once per block */
    ha_check_clean(&a);
    if (verbose())
        printf("  hostile: destroy in free hook of destroy: %d hooks, bad frees %ld (bound 0), live %lu (bound 0)\n",
               a.fired, a.bad_frees, (unsigned long)a.live_bytes);
}

/* ======================================== 3. allocator hooks re-entering */
/* Old bug: an alloc hook could create a body (or step, destroy, set) on
   the world that was allocating, in the middle of growing its arrays, so
   the world ended with bodies it had not counted or lost track of arrays.
   Now every such call is refused.  Bounds, exact: 40 bodies created from
   outside, 0 created from the hook, so 40 at the end; gravity as it was. */
static void alloc_hook_reentry_refused(void)
{
    hook_alloc a;
    ga2d_world_def wd;
    ga2d_world *w;
    ga2d_body_id ids[40];
    int i, valid = 0;
    ha_init(&a);
    wd = ha_world_def(&a);
    wd.gravity = vec(0, -10);
    w = ga2d_world_create(&wd);
    CHECK(w != NULL);
    if (!w) return;
    a.w = w;
    a.reenter_on_alloc = 1;
    for (i = 0; i < 40; ++i) {
        ga2d_body_def d = box_def(i == 0 ? GA2D_BODY_STATIC : GA2D_BODY_DYNAMIC, (i % 8) * 1.5, (i / 8) * 1.5, 0.5,
                                  0.5);
        ids[i] = ga2d_body_create(w, &d);
        CHECK(!ga2d_body_id_is_null(ids[i]));
        if (i == 0) a.probe = ids[0];
    }
    for (i = 0; i < 20; ++i) CHECK_RESULT(ga2d_world_step(w, (ga2d_real)(1.0 / 60)), GA2D_OK);
    for (i = 0; i < 40; ++i) valid += ga2d_body_is_valid(w, ids[i]) != 0;
    CHECK(a.fired > 0);
    CHECK(a.wrong == 0);
    CHECK(valid == 40);
    CHECK(ga2d_world_get_counters(w).body_count == 40);
    CHECK(vec_same(ga2d_world_gravity(w), vec(0, -10)));
    if (verbose())
        printf("  hostile: alloc hook re-entry: %d hooks, %d calls not refused (bound 0), %d bodies (bound 40)\n",
               a.fired, a.wrong, ga2d_world_get_counters(w).body_count);
    a.reenter_on_alloc = 0;
    ga2d_world_destroy(w);
    ha_check_clean(&a);
}

/* Old bug: ga2d_world_destroy freed the arrays while the world still
   pointed at them, so a free hook that read the world read freed memory.
   Now the world is emptied first: from a free hook of the destroy it reads
   as empty (body_count 0, its bodies invalid, no contacts).  The ASan
   configuration proves no freed memory is read. */
static void free_hook_reads_empty_world(void)
{
    hook_alloc a;
    ga2d_world_def wd;
    ga2d_world *w;
    ga2d_body_id ids[3];
    ha_init(&a);
    wd = ha_world_def(&a);
    w = ga2d_world_create(&wd);
    CHECK(w != NULL);
    if (!w) return;
    small_scene(w, ids);
    a.w = w;
    a.probe = ids[1];
    a.read_on_free = 1;
    ga2d_world_destroy(w);
    CHECK(a.fired > 0);
    CHECK(a.most_bodies_seen == 0);
    CHECK(a.valid_seen == 0);
    CHECK(a.wrong == 0);
    ha_check_clean(&a);
    if (verbose())
        printf("  hostile: free hook reads during destroy: %d reads, most bodies seen %d (bound 0)\n", a.fired,
               a.most_bodies_seen);
}

/* ============================================================ 4. tunnelling */
/* Old bug: a body's fat box was re-fitted only once the body had left it,
   stretched by v dt ahead, so a fast body re-fitted every other step and
   in between its box reached only the margin (0.1 m) ahead while it moved
   v dt.  A wall in that gap got no pair before the step, so no speculative
   contact, and the body jumped.  Why these sizes jump: a box of side s
   moving v dt per step overlaps a wall of thickness t at a step's end only
   if that end falls in a window of s + t of its path.  0.1 m box, 0.1 m
   wall, 30 m/s at 1/60 s: v dt = 0.5 m = 5 s, window 0.2 m, so 60 % of
   the phases jump from in front of the wall to behind it without an
   overlapping step; 0.5 m box, 0.5 m wall, 100 m/s: v dt = 1.67 m = 3.3 s,
   window 1 m, 40 % jump; and of the phases that land overlapping, those
   past the wall's middle are pushed out on the far side.  20 starts spread
   evenly over one step's travel try every phase to within v dt / 20.
   Bound: the box's centre stays on the near side of the wall's near face
   (x < -half wall) at the end and at every step on the way; resting
   against it the centre is at -(half wall + half box), and 120 steps are
   60 m / 200 m of free travel, so a box that got through is far beyond. */
static double tunnel_run(double half_box, double half_wall, double speed, double x0, double *most_out)
{
    ga2d_world_def wd = ga2d_default_world_def();
    ga2d_world *w;
    ga2d_body_def wall = box_def(GA2D_BODY_STATIC, 0, 0, half_wall, 10);
    ga2d_body_def box = box_def(GA2D_BODY_DYNAMIC, x0, 0, half_box, half_box);
    ga2d_body_id id;
    double most = -1e30;
    int i;
    wd.gravity = vec(0, 0);
    w = ga2d_world_create(&wd);
    *most_out = 1e30;
    if (!w) return 1e30;
    box.velocity = vec(speed, 0);
    CHECK(!ga2d_body_id_is_null(ga2d_body_create(w, &wall)));
    id = ga2d_body_create(w, &box);
    CHECK(!ga2d_body_id_is_null(id));
    for (i = 0; i < 120; ++i) {
        double x;
        CHECK_RESULT(ga2d_world_step(w, (ga2d_real)(1.0 / 60)), GA2D_OK);
        x = (double)ga2d_body_center(w, id).x;
        if (x > most) most = x;
    }
    *most_out = most;
    most = (double)ga2d_body_center(w, id).x; /* where it ended */
    ga2d_world_destroy(w);
    return most;
}

static void no_tunnelling(void)
{
    static const struct { double half_box, half_wall, speed; } cfg[2] = {{0.05, 0.05, 30}, {0.25, 0.25, 100}};
    int c, k;
    for (c = 0; c < 2; ++c) {
        double travel = cfg[c].speed / 60, worst_end = -1e30, worst_any = -1e30;
        int through = 0;
        for (k = 0; k < 20; ++k) {
            double x0 = -3 - k * travel / 20, most;
            double end = tunnel_run(cfg[c].half_box, cfg[c].half_wall, cfg[c].speed, x0, &most);
            if (!(end < -cfg[c].half_wall) || !(most < -cfg[c].half_wall)) {
                if (through++ < 3)
                    test_fail(__FILE__, __LINE__,
                              "%.2f m box at %.0f m/s from x0 = %.4f reached x = %.4f, ended at %.4f (bound < %.3f)",
                              2 * cfg[c].half_box, cfg[c].speed, x0, most, end, -cfg[c].half_wall);
            }
            if (end > worst_end) worst_end = end;
            if (most > worst_any) worst_any = most;
        }
        if (verbose())
            printf("  hostile: tunnelling %.2f m box at %.0f m/s: %d/20 through (bound 0), largest final centre x "
                   "%.4f (bound < %.3f; resting %.3f), largest at any step %.4f\n",
                   2 * cfg[c].half_box, cfg[c].speed, through, worst_end, -cfg[c].half_wall,
                   -cfg[c].half_wall - cfg[c].half_box, worst_any);
    }
}

/* ================================================ 5. sleep while embedded */
/* Old bug: the relax pass takes the push-out speed out of v, so a body
   still being pushed out of an overlap looked at rest, and after 0.5 s it
   fell asleep embedded (and stayed there: sleeping bodies are not
   pushed).  Now a contact deeper than the speculative distance (4 slops)
   keeps its bodies awake.  Bounds: asleep only while no deeper than
   GA2D_SPECULATIVE_DISTANCE (the rule itself); at the end out to within
   2 slops (the soft contact pushes until the overlap is within one slop,
   its target; gravity is off, so nothing presses it back in). */
static void no_sleep_embedded_in_ground(void)
{
    ga2d_world *w;
    ga2d_body_def ground = box_def(GA2D_BODY_STATIC, 0, -0.5, 5, 0.5);
    ga2d_body_def box = box_def(GA2D_BODY_DYNAMIC, 0, 0.25 - 0.6, 0.25, 0.25);
    ga2d_body_id id;
    const double asleep_bound = 0.25 - GA2D_SPECULATIVE_DISTANCE, end_bound = 0.25 - 2 * GA2D_LINEAR_SLOP;
    double lowest_asleep = 1e30, y = 0;
    int i, first_sleep = -1, bad = 0;
    w = weightless_world();
    CHECK(w != NULL);
    if (!w) return;
    CHECK(!ga2d_body_id_is_null(ga2d_body_create(w, &ground)));
    id = ga2d_body_create(w, &box);
    CHECK(!ga2d_body_id_is_null(id));
    for (i = 0; i < 600; ++i) {
        CHECK_RESULT(ga2d_world_step(w, (ga2d_real)(1.0 / 60)), GA2D_OK);
        y = (double)ga2d_body_center(w, id).y;
        if (!ga2d_body_is_awake(w, id)) {
            if (first_sleep < 0) first_sleep = i;
            if (y < lowest_asleep) lowest_asleep = y;
            if (!(y >= asleep_bound) && bad++ < 3)
                test_fail(__FILE__, __LINE__, "asleep at step %d with centre y = %.5f (bound >= %.5f)", i, y, asleep_bound);
        }
    }
    CHECK(y >= end_bound);
    if (verbose())
        printf("  hostile: embedded box: first asleep at step %d, lowest centre y asleep %.5f (bound >= %.5f), "
               "final %.5f (bound >= %.5f)\n",
               first_sleep, lowest_asleep, asleep_bound, y, end_bound);
    ga2d_world_destroy(w);
}

/* The same for two dynamic boxes created 98 % overlapped: neither may
   sleep while they overlap deeper than the speculative distance (centres
   closer than 0.5 - GA2D_SPECULATIVE_DISTANCE: the boxes stay axis
   aligned by symmetry, so the overlap is 0.5 - the centres' distance), and
   they end apart to within 2 slops. */
static void no_sleep_embedded_pair(void)
{
    ga2d_world *w;
    ga2d_body_def b1 = box_def(GA2D_BODY_DYNAMIC, 0, 0, 0.25, 0.25);
    ga2d_body_def b2 = box_def(GA2D_BODY_DYNAMIC, 0.01, 0, 0.25, 0.25);
    ga2d_body_id i1, i2;
    const double asleep_bound = 0.5 - GA2D_SPECULATIVE_DISTANCE, end_bound = 0.5 - 2 * GA2D_LINEAR_SLOP;
    double closest_asleep = 1e30, dist = 0;
    int i, first_sleep = -1, bad = 0;
    w = weightless_world();
    CHECK(w != NULL);
    if (!w) return;
    i1 = ga2d_body_create(w, &b1);
    i2 = ga2d_body_create(w, &b2);
    CHECK(!ga2d_body_id_is_null(i1) && !ga2d_body_id_is_null(i2));
    for (i = 0; i < 600; ++i) {
        ga2d_vec c1, c2;
        CHECK_RESULT(ga2d_world_step(w, (ga2d_real)(1.0 / 60)), GA2D_OK);
        c1 = ga2d_body_center(w, i1);
        c2 = ga2d_body_center(w, i2);
        dist = sqrt(((double)c2.x - (double)c1.x) * ((double)c2.x - (double)c1.x) +
                    ((double)c2.y - (double)c1.y) * ((double)c2.y - (double)c1.y));
        if (!ga2d_body_is_awake(w, i1) || !ga2d_body_is_awake(w, i2)) {
            if (first_sleep < 0) first_sleep = i;
            if (dist < closest_asleep) closest_asleep = dist;
            if (!(dist >= asleep_bound) && bad++ < 3)
                test_fail(__FILE__, __LINE__, "asleep at step %d with centres %.5f apart (bound >= %.5f)", i, dist,
                          asleep_bound);
        }
    }
    CHECK(dist >= end_bound);
    if (verbose())
        printf("  hostile: embedded pair: first asleep at step %d, closest asleep %.5f (bound >= %.5f), "
               "final %.5f (bound >= %.5f)\n",
               first_sleep, closest_asleep, asleep_bound, dist, end_bound);
    ga2d_world_destroy(w);
}

/* ============================================================ 6. thin arc */
/* Old bug: the incident edge was the one with the least n.m; for a thin,
   gently curved polygon every edge within sqrt(eps) of -n (3e-4 rad in
   float) rounds to n.m = -1, they all tie, and the first in index order
   won, not the lowest.  A 2 m arc of sagitta 0.19 mm lying on its curved
   side then rocked (|w| = 0.3 rad/s) and sat 2.4 cm deep.  The shape: 8
   vertices on a circle of radius R = (1 + s^2) / (2 s) = 2632 m, the ends
   at (+-1, 0) and 6 more evenly spaced in angle; its edges turn by
   2 asin(1/R) / 7 = 1.1e-4 rad each, all within that tie.  Bounds: it
   comes to rest (asleep at the end; asleep means w = 0 exactly) with its
   lowest vertex above the ground's top less 2 slops (a resting contact
   settles within one slop, the soft contact's target; the second covers
   gravity's sag within a substep, |g| h^2 = 0.17 mm, and rounding).  The
   tie is a float one: in double sqrt(eps) = 1.5e-8 rad is far below the
   edges' turn, so there the test checks the same rest without the old
   code failing it.
   Asleep is not at rest (sleeping zeroes the speeds), so the arc is also
   judged with sleep off, by its motion in the last of its 10 s: at rest,
   each substep gravity adds g h to v and the contact solve takes it out
   again, so what is left after a step is the rounding of some 8 terms of
   size g h: |v| <= 8 u g h, and the ends (1 m out) move no faster than
   3 times that (the arc's inertia m L^2 / 12 with L = 2 m takes the
   rounded point impulses at up to 1 m: |w| 1 m <= 3 (8 u g h) / 1 m).
   The old tie rocked it at 0.3 rad/s. */
static int arc_polygon(int curved_down, ga2d_polygon *out, double *lowest)
{
    const double s = 0.19e-3, R = (1 + s * s) / (2 * s), alpha = asin(1 / R);
    ga2d_vec up[8], pts[8];
    int k;
    /* bulging up, CCW: from (1, 0) over the arc to (-1, 0); the chord
       closes it along y = 0.  y = R (cos phi - cos alpha), written as a
       product of sines so the small heights keep their precision */
    for (k = 0; k < 8; ++k) {
        double phi = alpha - k * (2 * alpha / 7);
        up[k] = vec(R * sin(phi), 2 * R * sin((alpha + phi) / 2) * sin((alpha - phi) / 2));
    }
    up[0] = vec(1, 0);
    up[7] = vec(-1, 0);
    /* lying on its curved side: mirrored in y, reversed to stay CCW */
    for (k = 0; k < 8; ++k) pts[k] = curved_down ? vec((double)up[7 - k].x, -(double)up[7 - k].y) : up[k];
    *lowest = 0;
    for (k = 0; k < 8; ++k)
        if ((double)pts[k].y < *lowest) *lowest = (double)pts[k].y;
    return ga2d_polygon_make(pts, 8, out) == GA2D_OK;
}

static void thin_arc_comes_to_rest(void)
{
    int curved, order, sleep;
    for (sleep = 0; sleep < 2; ++sleep)
    for (curved = 0; curved < 2; ++curved)
        for (order = 0; order < 2; ++order) {
            ga2d_world_def wd = ga2d_default_world_def();
            ga2d_world *w;
            ga2d_body_def ground = box_def(GA2D_BODY_STATIC, 0, -0.5, 5, 0.5);
            ga2d_body_def arc = ga2d_default_body_def();
            ga2d_body_id id;
            double low_local, lowest = 1e30, late_spin = 0, late_speed = 0, bound = -2 * GA2D_LINEAR_SLOP;
            const double rest_speed = 8 * (REAL_EPS / 2) * 10 * (1.0 / 240);
            int i, k, spinning_asleep = 0, slept = 0;
            wd.enable_sleep = sleep;
            w = ga2d_world_create(&wd);
            arc.polygon = ga2d_polygon_box((ga2d_real)0.5, (ga2d_real)0.5);
            CHECK(w != NULL);
            if (!w) return;
            CHECK(arc_polygon(curved, &arc.polygon, &low_local));
            arc.type = GA2D_BODY_DYNAMIC;
            arc.position = vec(0, 0.05 - low_local); /* lowest point 5 cm up */
            if (order == 0) CHECK(!ga2d_body_id_is_null(ga2d_body_create(w, &ground)));
            id = ga2d_body_create(w, &arc);
            CHECK(!ga2d_body_id_is_null(id));
            if (order == 1) CHECK(!ga2d_body_id_is_null(ga2d_body_create(w, &ground)));
            for (i = 0; i < 600; ++i) {
                double om, sp;
                CHECK_RESULT(ga2d_world_step(w, (ga2d_real)(1.0 / 60)), GA2D_OK);
                om = fabs((double)ga2d_body_angular_velocity(w, id));
                sp = (double)ga2d_vec_length(ga2d_body_velocity(w, id));
                if (!ga2d_body_is_awake(w, id)) {
                    spinning_asleep += om != 0;
                    slept = 1;
                }
                if (i >= 540 && om > late_spin) late_spin = om;
                if (i >= 540 && sp > late_speed) late_speed = sp;
            }
            {
                ga2d_transform x = ga2d_body_transform(w, id);
                for (k = 0; k < arc.polygon.count; ++k) {
                    double y = (double)ga2d_transform_apply(x, arc.polygon.vertices[k]).y;
                    if (y < lowest) lowest = y;
                }
            }
            if (sleep) {
                CHECK(!ga2d_body_is_awake(w, id));
                CHECK(spinning_asleep == 0);
            } else {
                CHECK(!slept);
                CHECK(late_speed <= rest_speed);
                CHECK(late_spin * 1.0 <= 3 * rest_speed); /* the ends, 1 m out */
            }
            CHECK(lowest >= bound);
            if (verbose())
                printf("  hostile: thin arc %s, ground %s, sleep %s: %s, |w| in the last second %.3g, |v| %.3g, lowest point %.3g m "
                       "(bound >= %.5f)\n",
                       curved ? "curved side down" : "flat side down", order ? "after" : "before", sleep ? "on" : "off",
                       ga2d_body_is_awake(w, id) ? "awake" : "asleep", late_spin, late_speed, lowest, bound);
            ga2d_world_destroy(w);
        }
}

/* ============================================================ 7. small holes */
/* (a) Old bug: an id was slot + generation only, so world A's id named
   whatever body sat in the same slot of world B.  Now ids carry their
   world's tag (a 32-bit hash of its address: two live worlds' tags
   collide with odds 2^-32), and a snapshot carries it, so A's ids are
   valid in a world that loaded A. */
static void ids_belong_to_their_world(void)
{
    ga2d_world *a = ga2d_world_create(NULL), *b = ga2d_world_create(NULL);
    ga2d_body_def da = box_def(GA2D_BODY_DYNAMIC, 1, 2, 0.5, 0.5), db = box_def(GA2D_BODY_DYNAMIC, -3, 4, 0.5, 0.5);
    ga2d_body_id ia, ib;
    unsigned char *snap;
    size_t n;
    CHECK(a != NULL && b != NULL);
    if (!a || !b) {
        ga2d_world_destroy(a);
        ga2d_world_destroy(b);
        return;
    }
    ia = ga2d_body_create(a, &da);
    ib = ga2d_body_create(b, &db);
    CHECK(ia.index1 == ib.index1); /* the same slot */
    CHECK(ga2d_body_is_valid(a, ia) && ga2d_body_is_valid(b, ib));
    CHECK(!ga2d_body_is_valid(b, ia) && !ga2d_body_is_valid(a, ib));
    CHECK_RESULT(ga2d_body_set_velocity(b, ia, vec(1, 0)), GA2D_ERR_STALE_ID);
    CHECK_RESULT(ga2d_body_set_transform(b, ia, vec(7, 7), ga2d_rotor_identity()), GA2D_ERR_STALE_ID);
    CHECK_RESULT(ga2d_body_apply_impulse(b, ia, vec(1, 0), vec(0, 0)), GA2D_ERR_STALE_ID);
    CHECK_RESULT(ga2d_body_destroy(b, ia), GA2D_ERR_STALE_ID);
    CHECK(vec_same(ga2d_body_position(b, ib), vec(-3, 4)));
    CHECK(vec_same(ga2d_body_velocity(b, ib), vec(0, 0)));
    /* A loaded into B: A's ids name B's bodies now, B's old ones nothing */
    snap = world_bytes(a, &n);
    CHECK(snap != NULL);
    if (snap) {
        CHECK_RESULT(ga2d_world_snapshot_load(b, snap, n), GA2D_OK);
        CHECK(ga2d_body_is_valid(b, ia));
        CHECK(!ga2d_body_is_valid(b, ib));
        CHECK(vec_same(ga2d_body_position(b, ia), vec(1, 2)));
        CHECK_RESULT(ga2d_body_set_velocity(b, ib, vec(1, 0)), GA2D_ERR_STALE_ID);
        free(snap);
    }
    ga2d_world_destroy(a);
    ga2d_world_destroy(b);
}

/* (b) Old bug: ga2d_collide_polygons took any rotor and any hand-filled
   polygon: a zero rotor or an all-zero polygon gave a manifold with a
   zero or non-unit normal.  Now both are refused with *out untouched.
   Bound for the accepted rotor: the normal is a polygon normal (unit to
   an eps, from ga2d_vec_normalize) turned by a rotor q, |n q| = |n| |q|,
   and an accepted rotor has | |q|^2 - 1 | <= 1e-4, so | |n| - 1 | <=
   1e-4 / 2 + eps: the header's promise is unit within 1e-4.  A rotor from
   ga2d_rotor_from_angle is unit to a few eps, so the measured figure is
   of that order. */
static int out_untouched(const ga2d_manifold *m, const ga2d_manifold *ref)
{
    return memcmp(m, ref, sizeof *m) == 0;
}

static void collide_refuses_bad_input(void)
{
    ga2d_polygon box = ga2d_polygon_box((ga2d_real)0.5, (ga2d_real)0.5), zero;
    ga2d_transform xa = ga2d_transform_identity(), xb = ga2d_transform_make(vec(0.9, 0.1), ga2d_rotor_identity());
    ga2d_transform bad = xb;
    ga2d_manifold out, ref;
    double len;
    int n;
    memset(&ref, 0x5a, sizeof ref);
    /* zero rotor */
    bad.q.c = 0;
    bad.q.s = 0;
    out = ref;
    CHECK(ga2d_collide_polygons(&box, xa, &box, bad, &out) == -(int)GA2D_ERR_INVALID_ARGUMENT);
    CHECK(out_untouched(&out, &ref));
    out = ref;
    CHECK(ga2d_collide_polygons(&box, bad, &box, xb, &out) == -(int)GA2D_ERR_INVALID_ARGUMENT);
    CHECK(out_untouched(&out, &ref));
    /* |q|^2 = 1.01 */
    bad.q.c = (ga2d_real)sqrt(1.01);
    bad.q.s = 0;
    out = ref;
    CHECK(ga2d_collide_polygons(&box, xa, &box, bad, &out) == -(int)GA2D_ERR_INVALID_ARGUMENT);
    CHECK(out_untouched(&out, &ref));
    /* an all-zero hand-filled polygon */
    memset(&zero, 0, sizeof zero);
    zero.count = 4;
    out = ref;
    CHECK(ga2d_collide_polygons(&zero, xa, &box, xb, &out) < 0);
    CHECK(out_untouched(&out, &ref));
    out = ref;
    CHECK(ga2d_collide_polygons(&box, xa, &zero, xb, &out) < 0);
    CHECK(out_untouched(&out, &ref));
    /* a good rotor: accepted, unit normal */
    xb.q = ga2d_rotor_from_angle((ga2d_real)0.3);
    out = ref;
    n = ga2d_collide_polygons(&box, xa, &box, xb, &out);
    CHECK(n > 0);
    len = sqrt((double)out.normal.x * (double)out.normal.x + (double)out.normal.y * (double)out.normal.y);
    CHECK_NEAR(len, 1, 1e-4);
    if (verbose())
        printf("  hostile: collide with rotor_from_angle(0.3): %d points, | |n| - 1 | = %.3g (bound 1e-4)\n", n,
               fabs(len - 1));
}

/* (c) Old bug: coordinates were bounded for polygons only: a body could
   be placed, or given a centre of mass, at 1e30 (float: FLT_MAX), where
   every contact tolerance is below the spacing of representable numbers.
   Now beyond GA2D_MAX_COORDINATE is GA2D_ERR_TOO_LARGE, and a refused
   setter changes nothing (exact: same snapshot bytes). */
static void coordinates_are_bounded(void)
{
    ga2d_world *w = ga2d_world_create(NULL);
    ga2d_body_def d = box_def(GA2D_BODY_DYNAMIC, 0, 0, 0.5, 0.5);
    const double beyond = 2 * (double)GA2D_MAX_COORDINATE;
    const double huge_values[3] = {beyond, 1e30, REAL_MAX};
    ga2d_body_id id;
    unsigned char *before, *after;
    size_t nb, na;
    int k;
    CHECK(w != NULL);
    if (!w) return;
    id = ga2d_body_create(w, &d);
    CHECK(!ga2d_body_id_is_null(id));
    before = world_bytes(w, &nb);
    for (k = 0; k < 3; ++k) {
        ga2d_mass m = ga2d_body_mass_data(w, id);
        ga2d_body_def far = d;
        m.center = vec(huge_values[k], 0);
        CHECK_RESULT(ga2d_body_set_mass_data(w, id, m), GA2D_ERR_TOO_LARGE);
        m.center = vec(0, -huge_values[k]);
        CHECK_RESULT(ga2d_body_set_mass_data(w, id, m), GA2D_ERR_TOO_LARGE);
        CHECK_RESULT(ga2d_body_set_transform(w, id, vec(huge_values[k], 0), ga2d_rotor_identity()), GA2D_ERR_TOO_LARGE);
        CHECK_RESULT(ga2d_body_set_transform(w, id, vec(0, -huge_values[k]), ga2d_rotor_identity()), GA2D_ERR_TOO_LARGE);
        far.position = vec(huge_values[k], 0);
        CHECK_RESULT(ga2d_body_def_validate(&far), GA2D_ERR_TOO_LARGE);
        CHECK(ga2d_body_id_is_null(ga2d_body_create(w, &far)));
    }
    after = world_bytes(w, &na);
    CHECK(same_bytes(before, nb, after, na));
    CHECK(ga2d_world_get_counters(w).body_count == 1);
    free(before);
    free(after);
    ga2d_world_destroy(w);
}

/* (d) Old bug: a step of any length was taken (1000 s integrated gravity
   straight through the ground) and any finite gravity was accepted.  Now
   a step longer than GA2D_MAX_TIME_STEP, or whose substep h has
   |g| h^2 > GA2D_LINEAR_SLOP (gravity alone would move a resting body by
   more than a slop in one substep), is refused with TOO_LARGE and nothing
   changes; so is |g| > GA2D_MAX_GRAVITY.  The limit h = sqrt(slop / |g|)
   is tried at 1 -+ 1e-3 of itself: |g| h^2 then misses the slop by 2e-3
   relative, far above the few eps of rounding in dt / substeps, |g| and
   the product. */
static void step_and_gravity_are_bounded(void)
{
    ga2d_world_def wd = ga2d_default_world_def();
    ga2d_world *w;
    ga2d_body_id ids[3];
    unsigned char *before, *after;
    size_t nb, na;
    const double g = 10, dt_limit = 4 * sqrt(GA2D_LINEAR_SLOP / g);
    wd.gravity = vec(0, -g);
    wd.substeps = 4;
    w = ga2d_world_create(&wd);
    CHECK(w != NULL);
    if (!w) return;
    small_scene(w, ids);
    before = world_bytes(w, &nb);
    CHECK_RESULT(ga2d_world_step(w, (ga2d_real)1000), GA2D_ERR_TOO_LARGE);
    CHECK_RESULT(ga2d_world_step(w, (ga2d_real)(dt_limit * (1 + 1e-3))), GA2D_ERR_TOO_LARGE);
    CHECK_RESULT(ga2d_world_set_gravity(w, vec(0, -1e30)), GA2D_ERR_TOO_LARGE);
    CHECK_RESULT(ga2d_world_set_gravity(w, vec(0, -2 * GA2D_MAX_GRAVITY)), GA2D_ERR_TOO_LARGE);
    CHECK(vec_same(ga2d_world_gravity(w), vec(0, -g)));
    after = world_bytes(w, &na);
    CHECK(same_bytes(before, nb, after, na));
    CHECK_RESULT(ga2d_world_step(w, (ga2d_real)(dt_limit * (1 - 1e-3))), GA2D_OK);
    free(before);
    free(after);
    ga2d_world_destroy(w);
    /* a def with gravity beyond GA2D_MAX_GRAVITY */
    wd = ga2d_default_world_def();
    wd.gravity = vec(0, -2 * GA2D_MAX_GRAVITY);
    CHECK_RESULT(ga2d_world_def_validate(&wd), GA2D_ERR_TOO_LARGE);
    CHECK(ga2d_world_create(&wd) == NULL);
    if (verbose())
        printf("  hostile: step bound at g = 10, 4 substeps: dt limit %.6f s (refused at +0.1 %%, taken at -0.1 %%)\n",
               dt_limit);
}

/* ============================================================= 8. speed caps */
/* The cap on the drift itself: a solver pass can leave a body faster than
   the kick's cap, and the drift caps it again before it moves the body.
   YANK_PAIRS heavy boxes (1 m square, density 1000) fly at the cap, 400
   m/s along x, spinning at 100 rad/s, each with a light box (0.2 m
   square, density 1) on a revolute joint at 2 m from its centre, at rest:
   the joint drags the light box to the heavy one's point velocity there,
   |(400, 200)| = 447 m/s.  The soft step moves a body only in its drifts
   (x += v h, four a step, each v capped at 400 (1 + 16 eps) and then
   within a few ulps of it), so no centre moves more than 400 dt (1 + 64
   eps) in a step, rounding of the four sums included; uncapped, a light
   box would move up to 447 h in a substep, 3 % more in a step. */
#define YANK_PAIRS 8
static void yanked_past_the_cap(void)
{
    ga2d_world *w = weightless_world();
    ga2d_body_id heavy[YANK_PAIRS], light[YANK_PAIRS];
    ga2d_vec at[YANK_PAIRS];
    double dt = 1.0 / 60, worst = 0, bound = GA2D_MAX_LINEAR_SPEED * dt * (1 + 64 * REAL_EPS);
    int i, step, caps = 0;
    CHECK(w != NULL);
    if (!w) return;
    for (i = 0; i < YANK_PAIRS; ++i) {
        ga2d_body_def h = box_def(GA2D_BODY_DYNAMIC, 0, 10 * i, 0.5, 0.5), l = box_def(GA2D_BODY_DYNAMIC, 2, 10 * i, 0.1, 0.1);
        ga2d_revolute_joint_def j = ga2d_default_revolute_joint_def();
        h.density = 1000;
        h.velocity = vec(GA2D_MAX_LINEAR_SPEED, 0);
        h.angular_velocity = 100;
        heavy[i] = ga2d_body_create(w, &h);
        light[i] = ga2d_body_create(w, &l);
        j.body_a = heavy[i];
        j.body_b = light[i];
        j.local_anchor_a = vec(2, 0);
        j.local_anchor_b = vec(0, 0);
        CHECK(!ga2d_joint_id_is_null(ga2d_revolute_joint_create(w, &j)));
        at[i] = ga2d_body_center(w, light[i]);
    }
    for (step = 0; step < 5; ++step) {
        CHECK_RESULT(ga2d_world_step(w, (ga2d_real)dt), GA2D_OK);
        caps += ga2d_world_get_counters(w).speed_caps;
        for (i = 0; i < YANK_PAIRS; ++i) {
            ga2d_vec x = ga2d_body_center(w, light[i]);
            double dx = (double)x.x - (double)at[i].x, dy = (double)x.y - (double)at[i].y, d = sqrt(dx * dx + dy * dy);
            if (d > worst) worst = d;
            at[i] = x;
        }
    }
    CHECK(caps > 0);
    if (!(worst <= bound)) test_fail(__FILE__, __LINE__, "a light box moved %.9g m in a step, bound %.9g", worst, bound);
    ga2d_world_destroy(w);
}

/* A body that does not spin keeps its rotor to the bit, however far it is
   from unit length in its last bit (q (3 - |q|^2) / 2 would move it): 24
   boxes at angles 0.1 to 2.4 rad, at rest in a weightless world, 60
   steps. */
static void still_rotors_kept(void)
{
    ga2d_world *w = weightless_world();
    ga2d_body_id ids[24];
    ga2d_rotor q0[24];
    int i, step, changed = 0;
    CHECK(w != NULL);
    if (!w) return;
    for (i = 0; i < 24; ++i) {
        ga2d_body_def d = box_def(GA2D_BODY_DYNAMIC, 3 * i, 0, 0.5, 0.5);
        d.rotor = ga2d_rotor_from_angle((ga2d_real)(0.1 * (i + 1)));
        ids[i] = ga2d_body_create(w, &d);
        q0[i] = ga2d_body_rotor(w, ids[i]);
    }
    for (step = 0; step < 60; ++step) CHECK_RESULT(ga2d_world_step(w, (ga2d_real)(1.0 / 60)), GA2D_OK);
    for (i = 0; i < 24; ++i) {
        ga2d_rotor q = ga2d_body_rotor(w, ids[i]);
        changed += memcmp(&q, &q0[i], sizeof q) != 0;
    }
    CHECK(changed == 0);
    ga2d_world_destroy(w);
}
/* Old bug: a body driven past 400 m/s was capped silently, so a program
   whose scene was blowing up could not tell.  Now counters.speed_caps
   counts the caps of the last step.  The scene: a 1 kg box (1 m square,
   density 1) on an undamped spring k = 1e7 N/m towards the origin, from
   1 m, applied as a force before each step (explicit).  Its force gives
   a = 1e7 m/s^2 for the whole step (a force acts during the next step),
   so every substep (h = 1/240 s) adds 4.2e4 m/s, far past 400: the very
   first step must report a cap in each of its 4 substeps (one body: 4
   caps, exact; it does not turn, so no turn cap), and still return
   GA2D_OK.  A box resting on the ground never comes near 400 m/s:
   0 caps every step (exact). */
static void speed_caps_counted(void)
{
    ga2d_world *w;
    ga2d_body_def d = box_def(GA2D_BODY_DYNAMIC, 1, 0, 0.5, 0.5);
    ga2d_body_id id;
    const double k = 1e7;
    int i, first = -1, caps = 0, rest_caps = 0;
    w = weightless_world();
    CHECK(w != NULL);
    if (!w) return;
    id = ga2d_body_create(w, &d);
    CHECK(!ga2d_body_id_is_null(id));
    CHECK_NEAR(ga2d_body_mass_data(w, id).mass, 1, 4 * REAL_EPS);
    for (i = 0; i < 10; ++i) {
        ga2d_vec x = ga2d_body_center(w, id);
        CHECK_RESULT(ga2d_body_apply_force_to_center(w, id, vec(-k * (double)x.x, -k * (double)x.y)), GA2D_OK);
        CHECK_RESULT(ga2d_world_step(w, (ga2d_real)(1.0 / 60)), GA2D_OK);
        if (first < 0 && ga2d_world_get_counters(w).speed_caps > 0) {
            first = i;
            caps = ga2d_world_get_counters(w).speed_caps;
        }
    }
    CHECK(first == 0);
    CHECK(caps == 4);
    ga2d_world_destroy(w);

    /* a resting box */
    w = ga2d_world_create(NULL);
    CHECK(w != NULL);
    if (!w) return;
    {
        ga2d_body_def g = box_def(GA2D_BODY_STATIC, 0, -0.5, 5, 0.5), b = box_def(GA2D_BODY_DYNAMIC, 0, 0.5, 0.5, 0.5);
        CHECK(!ga2d_body_id_is_null(ga2d_body_create(w, &g)));
        CHECK(!ga2d_body_id_is_null(ga2d_body_create(w, &b)));
    }
    for (i = 0; i < 300; ++i) {
        CHECK_RESULT(ga2d_world_step(w, (ga2d_real)(1.0 / 60)), GA2D_OK);
        rest_caps += ga2d_world_get_counters(w).speed_caps;
    }
    CHECK(rest_caps == 0);
    ga2d_world_destroy(w);
    if (verbose())
        printf("  hostile: speed caps: stiff spring first capped at step %d (bound 0) with %d caps (bound 4); "
               "resting box %d caps in 300 steps (bound 0)\n",
               first, caps, rest_caps);
}

/* A body blown up by its own restitution (a finite but absurd e, whose
   rebound overflows to inf) is contained, and the NaN stops at the static
   ground: 0 x inf is NaN, so an impulse written to the ground's velocity
   would poison every later contact with it.  The ground's velocity stays
   exactly zero (it is never integrated), a box resting on the same ground
   ends as it would in a world without the blown-up body (it is the same
   world for it: the two never touch, and only the ground joins them), and
   nothing non-finite is read from any getter, also from the force
   callback, which the step calls after the restitution pass. */
static int field_saw_nan;
static void field_reads_all(ga2d_world *w, void *ctx)
{
    const ga2d_body_id *ids = (const ga2d_body_id *)ctx;
    int i;
    for (i = 0; i < 3; ++i) {
        ga2d_vec v = ga2d_body_velocity(w, ids[i]);
        ga2d_real om = ga2d_body_angular_velocity(w, ids[i]);
        if (!(v.x - v.x == 0 && v.y - v.y == 0 && om - om == 0)) field_saw_nan = 1;
    }
}

static void blowup_stops_at_ground(void)
{
    const ga2d_real huge_e = (ga2d_real)(sizeof(ga2d_real) == 4 ? 3e38 : 1e308);
    ga2d_world *w[2];
    ga2d_body_id ids[2][3];
    int k, i, results[2] = {0, 0};
    field_saw_nan = 0;
    for (k = 0; k < 2; ++k) {
        ga2d_world_def wd = ga2d_default_world_def();
        ga2d_body_def g = box_def(GA2D_BODY_STATIC, 0, -0.5, 20, 0.5);
        ga2d_body_def rest = box_def(GA2D_BODY_DYNAMIC, -5, 0.5, 0.5, 0.5);
        ga2d_body_def bad = box_def(GA2D_BODY_DYNAMIC, 5, 1.0, 0.5, 0.5);
        wd.force_callback = field_reads_all;
        wd.force_context = ids[k];
        w[k] = ga2d_world_create(&wd);
        CHECK(w[k] != NULL);
        if (!w[k]) return;
        bad.restitution = huge_e;
        bad.velocity = vec(0, -5);
        ids[k][0] = ga2d_body_create(w[k], &g);
        ids[k][1] = ga2d_body_create(w[k], &rest);
        /* the second world has the blown-up body's slot taken by a far
           away, harmless body, so that both worlds number alike */
        if (k == 1) bad.position = vec(5, 100), bad.restitution = 0;
        ids[k][2] = ga2d_body_create(w[k], &bad);
    }
    for (i = 0; i < 120; ++i)
        for (k = 0; k < 2; ++k) {
            ga2d_result r = ga2d_world_step(w[k], (ga2d_real)(1.0 / 60));
            if (r != GA2D_OK) ++results[k];
            CHECK(vec_same(ga2d_body_velocity(w[k], ids[k][0]), vec(0, 0)));
            CHECK(ga2d_body_angular_velocity(w[k], ids[k][0]) == 0);
        }
    CHECK(results[0] > 0);  /* the blow-up is reported (NOT_FINITE) */
    CHECK(results[1] == 0);
    CHECK(!field_saw_nan);
    /* the resting box: bit for bit as in the world without the blow-up */
    CHECK(vec_same(ga2d_body_center(w[0], ids[0][1]), ga2d_body_center(w[1], ids[1][1])));
    CHECK(vec_same(ga2d_body_velocity(w[0], ids[0][1]), ga2d_body_velocity(w[1], ids[1][1])));
    if (verbose())
        printf("  hostile: blow-up at the ground: %d steps reported it; resting box at y = %.6f in both worlds\n",
               results[0], (double)ga2d_body_center(w[0], ids[0][1]).y);
    ga2d_world_destroy(w[0]);
    ga2d_world_destroy(w[1]);
}

void suite_hostile(void)
{
    test_run("hostile: draw callbacks are locked", draw_callbacks_are_locked);
    test_run("hostile: destroy from the force callback", destroy_from_force_callback);
    test_run("hostile: destroy from a draw callback", destroy_from_draw_callback);
    test_run("hostile: destroy from an alloc hook", destroy_from_alloc_hook);
    test_run("hostile: destroy from a free hook of destroy", destroy_from_free_hook);
    test_run("hostile: alloc hook re-entry refused", alloc_hook_reentry_refused);
    test_run("hostile: free hook reads an empty world", free_hook_reads_empty_world);
    test_run("hostile: no tunnelling through thin walls", no_tunnelling);
    test_run("hostile: no sleep embedded in the ground", no_sleep_embedded_in_ground);
    test_run("hostile: no sleep embedded in a pair", no_sleep_embedded_pair);
    test_run("hostile: thin arc comes to rest", thin_arc_comes_to_rest);
    test_run("hostile: ids belong to their world", ids_belong_to_their_world);
    test_run("hostile: collide refuses bad input", collide_refuses_bad_input);
    test_run("hostile: coordinates are bounded", coordinates_are_bounded);
    test_run("hostile: step and gravity are bounded", step_and_gravity_are_bounded);
    test_run("hostile: speed caps counted", speed_caps_counted);
    test_run("hostile: a body a joint yanks past the speed cap drifts no faster than it", yanked_past_the_cap);
    test_run("hostile: bodies that do not spin keep their rotors to the bit", still_rotors_kept);
    test_run("hostile: a blow-up stops at the ground", blowup_stops_at_ground);
}
