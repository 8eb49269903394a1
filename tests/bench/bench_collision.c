/* bench_collision.c - broadphase and narrowphase alone (a benchmark, not a test).

   Broadphase: the header's dynamic AABB tree (ga2d__tree_*, driven the way
   the step's broadphase stages drive it: fat boxes moved only when a body leaves
   them, a move buffer, queries of the moved proxies against the moving tree
   and, for moving bodies, the static tree, a hashed pair set, ended pairs
   found by re-testing every pair's fat boxes) against a sort-and-sweep
   written here for the comparison (same fat boxes, same refit rule,
   insertion sort by lower bound each step, a full sweep, radix-sorted pair
   keys diffed against the last step's set).  Both deliver the same pair set
   and the same new/ended pairs each step; that is checked.

   Scenes, n = 100, 1 000, 10 000, 50 000 bodies at constant density (one
   body per 4 m^2): "moving" (speeds up to 5 m/s, 10% static, wrap-around)
   and "resting" (the same bodies still, a 1e-3 m jitter per step).
   Each (scene, n) is timed in alternating runs of the two structures, each
   run from the same start state; medians and minima over the runs, and the
   ratio SAP / tree of the medians.  Then ga2d_collide_polygons alone over the
   moving scene's pairs, and the full ga2d_world_step (gravity 0, 1 substep)
   for reference.

   Build (from the repository root):
     gcc -std=c99 -O2 -g -ffp-contract=off -Wall -Wextra -Wpedantic -Wshadow \
         -Wdouble-promotion -Werror -I. tests/bench/bench_collision.c \
         -o build/bench/bench_collision -lm
   Run: build/bench/bench_collision [out.csv]                                  */
#define _POSIX_C_SOURCE 199309L
#define GA2D_IMPLEMENTATION
#include "ga2d_physics.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* ------------------------------------------------------------------ utils */
static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void *xmalloc(size_t size)
{
    void *p = malloc(size ? size : 1);
    if (!p) {
        fprintf(stderr, "bench_collision: out of memory\n");
        exit(2);
    }
    return p;
}

static void *xcalloc(size_t count, size_t size)
{
    void *p = calloc(count ? count : 1, size ? size : 1);
    if (!p) {
        fprintf(stderr, "bench_collision: out of memory\n");
        exit(2);
    }
    return p;
}

static int cmp_double(const void *x, const void *y)
{
    double a = *(const double *)x, b = *(const double *)y;
    return (a > b) - (a < b);
}

static double median(const double *v, int n)
{
    double tmp[64];
    int i;
    if (n > 64) n = 64;
    for (i = 0; i < n; ++i) tmp[i] = v[i];
    qsort(tmp, (size_t)n, sizeof *tmp, cmp_double);
    return n % 2 ? tmp[n / 2] : 0.5 * (tmp[n / 2 - 1] + tmp[n / 2]);
}

static double minimum(const double *v, int n)
{
    double m = v[0];
    int i;
    for (i = 1; i < n; ++i) m = v[i] < m ? v[i] : m;
    return m;
}

/* splitmix64 */
static uint64_t rng_next(uint64_t *s)
{
    uint64_t z = (*s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}
static double rng_unit(uint64_t *s) { return (double)(rng_next(s) >> 11) * (1.0 / 9007199254740992.0); }

static uint64_t pair_key(int a, int b)
{
    return a < b ? ((uint64_t)(uint32_t)a << 32) | (uint32_t)b : ((uint64_t)(uint32_t)b << 32) | (uint32_t)a;
}

static int cmp_u64(const void *x, const void *y)
{
    uint64_t a = *(const uint64_t *)x, b = *(const uint64_t *)y;
    return (a > b) - (a < b);
}

#define MARGIN GA2D__R(GA2D_AABB_MARGIN)
#define DT GA2D__R(1.0 / 60.0)
#define AREA_PER_BODY 4.0 /* m^2: constant density */
#define STATIC_FRACTION 0.1
#define MAX_SPEED 5.0
#define JITTER 1e-3
#define WARMUP 10

/* ------------------------------------------------------------------ scene */
typedef struct scene {
    int n, resting;
    ga2d_real side;
    ga2d_polygon *poly;
    ga2d_rotor *q;
    ga2d_vec *p0, *p, *v;
    unsigned char *is_static;
    int *moving;
    int moving_count;
    uint64_t rng0, rng;
} scene;

/* The same bodies for a given n whatever the scene (same seed); the
   resting scene only zeroes the velocities. */
static void scene_init(scene *sc, int n, int resting)
{
    uint64_t r = 0x5eed0000ull + (uint64_t)n;
    int i;
    memset(sc, 0, sizeof *sc);
    sc->n = n;
    sc->resting = resting;
    sc->side = (ga2d_real)sqrt((double)n * AREA_PER_BODY);
    sc->poly = (ga2d_polygon *)xmalloc((size_t)n * sizeof *sc->poly);
    sc->q = (ga2d_rotor *)xmalloc((size_t)n * sizeof *sc->q);
    sc->p0 = (ga2d_vec *)xmalloc((size_t)n * sizeof *sc->p0);
    sc->p = (ga2d_vec *)xmalloc((size_t)n * sizeof *sc->p);
    sc->v = (ga2d_vec *)xmalloc((size_t)n * sizeof *sc->v);
    sc->is_static = (unsigned char *)xmalloc((size_t)n);
    sc->moving = (int *)xmalloc((size_t)n * sizeof *sc->moving);
    for (i = 0; i < n; ++i) {
        double speed, dir;
        sc->is_static[i] = rng_unit(&r) < STATIC_FRACTION;
        if (rng_unit(&r) < 0.5) {
            double w = 0.3 + 1.2 * rng_unit(&r), h = 0.3 + 1.2 * rng_unit(&r);
            sc->poly[i] = ga2d_polygon_box((ga2d_real)(0.5 * w), (ga2d_real)(0.5 * h));
        } else {
            int k = 3 + (int)(rng_next(&r) % 6u);
            double d = 0.3 + 1.2 * rng_unit(&r);
            if (k > GA2D_MAX_POLYGON_VERTICES) k = GA2D_MAX_POLYGON_VERTICES;
            sc->poly[i] = ga2d_polygon_regular(k, (ga2d_real)(0.5 * d));
        }
        if (sc->poly[i].count < 3) {
            fprintf(stderr, "bench_collision: polygon construction failed\n");
            exit(2);
        }
        sc->q[i] = ga2d_rotor_from_angle((ga2d_real)(6.283185307179586 * rng_unit(&r)));
        sc->p0[i] = ga2d_vec_make((ga2d_real)((double)sc->side * rng_unit(&r)),
                                  (ga2d_real)((double)sc->side * rng_unit(&r)));
        speed = MAX_SPEED * rng_unit(&r);
        dir = 6.283185307179586 * rng_unit(&r);
        sc->v[i] = ga2d_vec_make((ga2d_real)(speed * cos(dir)), (ga2d_real)(speed * sin(dir)));
        if (sc->is_static[i] || resting) sc->v[i] = ga2d_vec_make(0, 0);
        if (!sc->is_static[i]) sc->moving[sc->moving_count++] = i;
    }
    sc->rng0 = r;
    memcpy(sc->p, sc->p0, (size_t)n * sizeof *sc->p);
    sc->rng = sc->rng0;
}

static void scene_reset(scene *sc)
{
    memcpy(sc->p, sc->p0, (size_t)sc->n * sizeof *sc->p);
    sc->rng = sc->rng0;
}

static void scene_free(scene *sc)
{
    free(sc->poly);
    free(sc->q);
    free(sc->p0);
    free(sc->p);
    free(sc->v);
    free(sc->is_static);
    free(sc->moving);
}

/* One step of motion (not timed): drift or jitter, wrap at the edges. */
static void scene_advance(scene *sc)
{
    int k;
    for (k = 0; k < sc->moving_count; ++k) {
        int i = sc->moving[k];
        ga2d_vec p = sc->p[i];
        if (sc->resting) {
            p.x += (ga2d_real)(JITTER * (2 * rng_unit(&sc->rng) - 1));
            p.y += (ga2d_real)(JITTER * (2 * rng_unit(&sc->rng) - 1));
        } else {
            p.x += sc->v[i].x * DT;
            p.y += sc->v[i].y * DT;
        }
        if (p.x < 0) p.x += sc->side;
        else if (p.x >= sc->side) p.x -= sc->side;
        if (p.y < 0) p.y += sc->side;
        else if (p.y >= sc->side) p.y -= sc->side;
        sc->p[i] = p;
    }
}

static ga2d_aabb body_aabb(const scene *sc, int i)
{
    return ga2d_polygon_aabb(&sc->poly[i], ga2d_transform_make(sc->p[i], sc->q[i]));
}

/* What a broadphase step delivered: the pair set (sorted keys) and how many
   pairs began and ended since it was built. */
typedef struct bp_result {
    uint64_t *pairs;
    int count;
    long long began, ended, refits;
} bp_result;

/* ------------------------------------------------------- tree broadphase */
/* Mirrors the world: trees[0] static bodies, trees[1] moving ones; the pair
   set is the header's own hash (ga2d__pairs_*) in a scratch world, plus a
   dense list standing in for the world's contact pool. */
typedef struct tree_bp {
    const scene *sc;
    ga2d_allocator alloc;
    ga2d__tree trees[2];
    int *proxy;
    unsigned char *in_move;
    int *move_buf;
    int move_count;
    uint64_t *new_pairs;
    int new_count, new_cap;
    ga2d_world *w;      /* its pair hash only */
    uint64_t *list;     /* the pairs, unordered */
    int list_count, list_cap;
    long long began, ended, refits;
} tree_bp;

typedef struct tree_query_ctx { tree_bp *bp; int self; } tree_query_ctx;

static void tree_pair_found(void *ctx, int other)
{
    tree_query_ctx *q = (tree_query_ctx *)ctx;
    tree_bp *bp = q->bp;
    uint64_t key;
    if (other == q->self) return;
    if (bp->in_move[other] && other < q->self) return; /* the smaller queued slot finds it */
    if (bp->sc->is_static[other] && bp->sc->is_static[q->self]) return;
    key = pair_key(q->self, other);
    if (ga2d__pairs_has(bp->w, key)) return;
    if (bp->new_count == bp->new_cap) {
        bp->new_cap = bp->new_cap ? 2 * bp->new_cap : 1024;
        bp->new_pairs = (uint64_t *)realloc(bp->new_pairs, (size_t)bp->new_cap * sizeof *bp->new_pairs);
        if (!bp->new_pairs) exit(2);
    }
    bp->new_pairs[bp->new_count++] = key;
}

static ga2d__tree *tree_of(tree_bp *bp, int i) { return &bp->trees[!bp->sc->is_static[i]]; }

static void tree_buffer_move(tree_bp *bp, int i)
{
    if (bp->in_move[i]) return;
    bp->in_move[i] = 1;
    bp->move_buf[bp->move_count++] = i;
}

/* New pairs from the move buffer, then ended pairs by re-testing boxes. */
static void tree_find_pairs(tree_bp *bp)
{
    int k, n;
    if (bp->move_count > 1) qsort(bp->move_buf, (size_t)bp->move_count, sizeof *bp->move_buf, ga2d__cmp_int);
    bp->new_count = 0;
    for (k = 0; k < bp->move_count; ++k) {
        int i = bp->move_buf[k];
        tree_query_ctx q;
        ga2d_aabb box = tree_of(bp, i)->nodes[bp->proxy[i]].box;
        q.bp = bp;
        q.self = i;
        ga2d__tree_query(&bp->trees[1], box, GA2D__ALL_CATEGORIES, tree_pair_found, &q);
        if (!bp->sc->is_static[i]) ga2d__tree_query(&bp->trees[0], box, GA2D__ALL_CATEGORIES, tree_pair_found, &q);
    }
    if (bp->new_count > 1) qsort(bp->new_pairs, (size_t)bp->new_count, sizeof *bp->new_pairs, ga2d__cmp_u64);
    for (k = 0, n = bp->new_count; k < n; ++k) {
        uint64_t key = bp->new_pairs[k];
        if (k > 0 && bp->new_pairs[k - 1] == key) continue;
        if (!ga2d__pairs_reserve(bp->w)) exit(2);
        ga2d__pairs_put(bp->w->pair_keys, bp->w->pair_capacity, key);
        ++bp->w->contact_count; /* the pair set's fill: one key per contact (ga2d__pairs_reserve) */
        if (bp->list_count == bp->list_cap) {
            bp->list_cap = bp->list_cap ? 2 * bp->list_cap : 1024;
            bp->list = (uint64_t *)realloc(bp->list, (size_t)bp->list_cap * sizeof *bp->list);
            if (!bp->list) exit(2);
        }
        bp->list[bp->list_count++] = key;
        ++bp->began;
    }
    for (k = 0; k < bp->move_count; ++k) bp->in_move[bp->move_buf[k]] = 0;
    bp->move_count = 0;
    /* the world does this in its narrowphase loop, over every contact */
    for (k = 0; k < bp->list_count; ++k) {
        uint64_t key = bp->list[k];
        int a = (int)(key >> 32), b = (int)(uint32_t)key;
        if (ga2d_aabb_overlaps(tree_of(bp, a)->nodes[bp->proxy[a]].box, tree_of(bp, b)->nodes[bp->proxy[b]].box))
            continue;
        ga2d__pairs_remove(bp->w, key);
        --bp->w->contact_count;
        bp->list[k--] = bp->list[--bp->list_count];
        ++bp->ended;
    }
}

static void tree_build(tree_bp *bp, const scene *sc)
{
    int i, n = sc->n, moving = sc->moving_count;
    memset(bp, 0, sizeof *bp);
    bp->sc = sc;
    bp->trees[0].root = bp->trees[0].free_list = -1;
    bp->trees[1].root = bp->trees[1].free_list = -1;
    if (!ga2d__tree_reserve(&bp->alloc, &bp->trees[0], n - moving) || !ga2d__tree_reserve(&bp->alloc, &bp->trees[1], moving))
        exit(2);
    bp->proxy = (int *)xmalloc((size_t)n * sizeof *bp->proxy);
    bp->in_move = (unsigned char *)xcalloc((size_t)n, 1);
    bp->move_buf = (int *)xmalloc((size_t)n * sizeof *bp->move_buf);
    bp->w = ga2d_world_create(NULL);
    if (!bp->w) exit(2);
    for (i = 0; i < n; ++i) {
        bp->proxy[i] = ga2d__tree_create(tree_of(bp, i), ga2d__fatten(body_aabb(sc, i), MARGIN), i, 1u); /* category 1, as a default shape */
        tree_buffer_move(bp, i);
    }
    tree_find_pairs(bp);
    bp->began = bp->ended = 0;
}

/* One broadphase step (timed): refit the bodies that left their fat boxes,
   then pairs. */
static void tree_step(tree_bp *bp)
{
    const scene *sc = bp->sc;
    ga2d__tree *t = &bp->trees[1];
    int k;
    for (k = 0; k < sc->moving_count; ++k) {
        int i = sc->moving[k];
        ga2d_aabb box = body_aabb(sc, i);
        if (ga2d_aabb_contains(t->nodes[bp->proxy[i]].box, box)) continue;
        ga2d__tree_move(t, bp->proxy[i], ga2d__fatten(box, MARGIN));
        tree_buffer_move(bp, i);
        ++bp->refits;
    }
    tree_find_pairs(bp);
}

static void tree_result(const tree_bp *bp, bp_result *out)
{
    out->count = bp->list_count;
    out->pairs = (uint64_t *)xmalloc((size_t)(bp->list_count + 1) * sizeof *out->pairs);
    memcpy(out->pairs, bp->list, (size_t)bp->list_count * sizeof *bp->list);
    qsort(out->pairs, (size_t)out->count, sizeof *out->pairs, cmp_u64);
    out->began = bp->began;
    out->ended = bp->ended;
    out->refits = bp->refits;
}

static void tree_free(tree_bp *bp)
{
    ga2d__tree_release(&bp->alloc, &bp->trees[0]);
    ga2d__tree_release(&bp->alloc, &bp->trees[1]);
    free(bp->proxy);
    free(bp->in_move);
    free(bp->move_buf);
    free(bp->new_pairs);
    free(bp->list);
    ga2d_world_destroy(bp->w);
}

/* Diagnostics (not timed): height, nodes visited per query and the tree's
   SAH cost (sum of inner perimeters over the root's). */
typedef struct tree_stats { int leaves, height; double visits, hits, sah; } tree_stats;

static void tree_stats_of(tree_bp *bp, tree_stats *st)
{
    const ga2d__tree *t = &bp->trees[1];
    const scene *sc = bp->sc;
    long long visits = 0, hits = 0;
    double inner = 0;
    int k, i;
    memset(st, 0, sizeof *st);
    if (t->root < 0) return;
    st->leaves = t->leaves;
    st->height = t->nodes[t->root].height;
    for (i = 0; i < t->used; ++i)
        if (t->nodes[i].height > 0) inner += (double)ga2d__perimeter(t->nodes[i].box);
    st->sah = inner / (double)ga2d__perimeter(t->nodes[t->root].box);
    for (k = 0; k < sc->moving_count; ++k) {
        int stack[256], top = 0;
        ga2d_aabb q = t->nodes[bp->proxy[sc->moving[k]]].box;
        stack[top++] = t->root;
        while (top > 0) {
            const ga2d__node *nd = &t->nodes[stack[--top]];
            ++visits;
            if (!ga2d_aabb_overlaps(nd->box, q)) continue;
            if (nd->child1 < 0) {
                ++hits;
            } else {
                stack[top++] = nd->child2;
                stack[top++] = nd->child1;
            }
        }
    }
    st->visits = (double)visits / (double)(sc->moving_count ? sc->moving_count : 1);
    st->hits = (double)hits / (double)(sc->moving_count ? sc->moving_count : 1);
}

/* --------------------------------------------------------- sort and sweep */
typedef struct sap_entry {
    ga2d_real lo, hi;   /* on the sweep axis */
    ga2d_real olo, ohi; /* on the other axis */
    int id, is_static;
} sap_entry;

typedef struct sap_bp {
    const scene *sc;
    int axis;           /* 0: x, 1: y */
    int bits;           /* bits of a body index */
    ga2d_aabb *fat;     /* per body */
    sap_entry *e;       /* sorted by lo */
    int *pos;           /* body -> index in e */
    uint64_t *cur, *prev, *tmp, *began_list, *ended_list;
    int cur_count, prev_count, began_count, ended_count, cap;
    long long began, ended, refits;
} sap_bp;

static void sap_entry_set(sap_bp *s, sap_entry *en, int i)
{
    ga2d_aabb b = s->fat[i];
    en->lo = s->axis ? b.lower.y : b.lower.x;
    en->hi = s->axis ? b.upper.y : b.upper.x;
    en->olo = s->axis ? b.lower.x : b.lower.y;
    en->ohi = s->axis ? b.upper.x : b.upper.y;
    en->id = i;
    en->is_static = s->sc->is_static[i];
}

static void sap_push(sap_bp *s, uint64_t key)
{
    if (s->cur_count == s->cap) {
        s->cap *= 2;
        s->cur = (uint64_t *)realloc(s->cur, (size_t)s->cap * sizeof *s->cur);
        s->prev = (uint64_t *)realloc(s->prev, (size_t)s->cap * sizeof *s->prev);
        s->tmp = (uint64_t *)realloc(s->tmp, (size_t)s->cap * sizeof *s->tmp);
        s->began_list = (uint64_t *)realloc(s->began_list, (size_t)s->cap * sizeof *s->began_list);
        s->ended_list = (uint64_t *)realloc(s->ended_list, (size_t)s->cap * sizeof *s->ended_list);
        if (!s->cur || !s->prev || !s->tmp || !s->began_list || !s->ended_list) exit(2);
    }
    s->cur[s->cur_count++] = key;
}

/* LSD radix sort of the keys (a << 32 | b, a < b < 2^bits) on the packed
   value a << bits | b, 11 bits a pass; insertion sort when short. */
static void sap_sort_keys(sap_bp *s)
{
    uint64_t *src = s->cur, *dst = s->tmp, *t;
    int n = s->cur_count, total = 2 * s->bits, shift, i;
    if (n < 64) {
        for (i = 1; i < n; ++i) {
            uint64_t x = src[i];
            int j = i;
            while (j > 0 && src[j - 1] > x) {
                src[j] = src[j - 1];
                --j;
            }
            src[j] = x;
        }
        return;
    }
    for (shift = 0; shift < total; shift += 11) {
        int count[2048];
        memset(count, 0, sizeof count);
        for (i = 0; i < n; ++i) {
            uint64_t k = src[i], packed = ((k >> 32) << s->bits) | (k & 0xffffffffu);
            ++count[(packed >> shift) & 2047u];
        }
        {
            int sum = 0, d;
            for (d = 0; d < 2048; ++d) {
                int c = count[d];
                count[d] = sum;
                sum += c;
            }
        }
        for (i = 0; i < n; ++i) {
            uint64_t k = src[i], packed = ((k >> 32) << s->bits) | (k & 0xffffffffu);
            dst[count[(packed >> shift) & 2047u]++] = k;
        }
        t = src;
        src = dst;
        dst = t;
    }
    if (src != s->cur) { /* an odd number of passes: the result is in tmp */
        s->tmp = s->cur;
        s->cur = src;
    }
}

/* The sweep (every pair of overlapping boxes, not both static), sorted,
   then merged against the last step's set: began and ended pairs. */
static void sap_sweep_and_diff(sap_bp *s)
{
    const sap_entry *e = s->e;
    int n = s->sc->n, i, a, b;
    uint64_t *t;
    t = s->prev;
    s->prev = s->cur;
    s->cur = t;
    s->prev_count = s->cur_count;
    s->cur_count = 0;
    for (i = 0; i < n; ++i) {
        sap_entry x = e[i];
        int j;
        for (j = i + 1; j < n && e[j].lo <= x.hi; ++j) {
            if (x.is_static && e[j].is_static) continue;
            if (e[j].olo <= x.ohi && x.olo <= e[j].ohi) sap_push(s, pair_key(x.id, e[j].id));
        }
    }
    sap_sort_keys(s);
    s->began_count = s->ended_count = 0;
    for (a = 0, b = 0; a < s->cur_count || b < s->prev_count;) {
        if (b == s->prev_count || (a < s->cur_count && s->cur[a] < s->prev[b])) s->began_list[s->began_count++] = s->cur[a++];
        else if (a == s->cur_count || s->prev[b] < s->cur[a]) s->ended_list[s->ended_count++] = s->prev[b++];
        else ++a, ++b;
    }
    s->began += s->began_count;
    s->ended += s->ended_count;
}

static int cmp_entry(const void *x, const void *y)
{
    ga2d_real a = ((const sap_entry *)x)->lo, b = ((const sap_entry *)y)->lo;
    return (a > b) - (a < b);
}

static void sap_build(sap_bp *s, const scene *sc)
{
    int i, n = sc->n;
    double mean[2] = {0, 0}, var[2] = {0, 0};
    memset(s, 0, sizeof *s);
    s->sc = sc;
    while ((1 << s->bits) < n) ++s->bits;
    s->fat = (ga2d_aabb *)xmalloc((size_t)n * sizeof *s->fat);
    s->e = (sap_entry *)xmalloc((size_t)n * sizeof *s->e);
    s->pos = (int *)xmalloc((size_t)n * sizeof *s->pos);
    s->cap = 1024;
    s->cur = (uint64_t *)xmalloc((size_t)s->cap * sizeof *s->cur);
    s->prev = (uint64_t *)xmalloc((size_t)s->cap * sizeof *s->prev);
    s->tmp = (uint64_t *)xmalloc((size_t)s->cap * sizeof *s->tmp);
    s->began_list = (uint64_t *)xmalloc((size_t)s->cap * sizeof *s->began_list);
    s->ended_list = (uint64_t *)xmalloc((size_t)s->cap * sizeof *s->ended_list);
    for (i = 0; i < n; ++i) {
        s->fat[i] = ga2d__fatten(body_aabb(sc, i), MARGIN);
        mean[0] += 0.5 * ((double)s->fat[i].lower.x + (double)s->fat[i].upper.x);
        mean[1] += 0.5 * ((double)s->fat[i].lower.y + (double)s->fat[i].upper.y);
    }
    mean[0] /= n;
    mean[1] /= n;
    for (i = 0; i < n; ++i) {
        double cx = 0.5 * ((double)s->fat[i].lower.x + (double)s->fat[i].upper.x) - mean[0];
        double cy = 0.5 * ((double)s->fat[i].lower.y + (double)s->fat[i].upper.y) - mean[1];
        var[0] += cx * cx;
        var[1] += cy * cy;
    }
    /* sweep along the axis the boxes are spread most along: fewest false
       overlaps on it (equal here, the level is square) */
    s->axis = var[1] > var[0];
    for (i = 0; i < n; ++i) sap_entry_set(s, &s->e[i], i);
    qsort(s->e, (size_t)n, sizeof *s->e, cmp_entry);
    for (i = 0; i < n; ++i) s->pos[s->e[i].id] = i;
    sap_sweep_and_diff(s);
    s->began = s->ended = 0;
}

/* One broadphase step (timed). */
static void sap_step(sap_bp *s)
{
    const scene *sc = s->sc;
    sap_entry *e = s->e;
    int k, i, n = sc->n;
    for (k = 0; k < sc->moving_count; ++k) {
        ga2d_aabb box;
        i = sc->moving[k];
        box = body_aabb(sc, i);
        if (ga2d_aabb_contains(s->fat[i], box)) continue;
        s->fat[i] = ga2d__fatten(box, MARGIN);
        sap_entry_set(s, &e[s->pos[i]], i);
        ++s->refits;
    }
    /* insertion sort: nearly sorted from the last step */
    for (i = 1; i < n; ++i) {
        sap_entry x;
        int j = i;
        if (e[i - 1].lo <= e[i].lo) continue;
        x = e[i];
        while (j > 0 && e[j - 1].lo > x.lo) {
            e[j] = e[j - 1];
            s->pos[e[j].id] = j;
            --j;
        }
        e[j] = x;
        s->pos[x.id] = j;
    }
    sap_sweep_and_diff(s);
}

static void sap_result(const sap_bp *s, bp_result *out)
{
    out->count = s->cur_count;
    out->pairs = (uint64_t *)xmalloc((size_t)(s->cur_count + 1) * sizeof *out->pairs);
    memcpy(out->pairs, s->cur, (size_t)s->cur_count * sizeof *s->cur);
    out->began = s->began;
    out->ended = s->ended;
    out->refits = s->refits;
}

static void sap_free(sap_bp *s)
{
    free(s->fat);
    free(s->e);
    free(s->pos);
    free(s->cur);
    free(s->prev);
    free(s->tmp);
    free(s->began_list);
    free(s->ended_list);
}

/* ------------------------------------------------------------- validation */
static void check_same(const bp_result *t, const bp_result *s, const char *scene_name, int n, const char *when)
{
    int i;
    if (t->count != s->count || memcmp(t->pairs, s->pairs, (size_t)t->count * sizeof *t->pairs) != 0) {
        int shown = 0;
        fprintf(stderr, "bench_collision: %s n=%d %s: tree has %d pairs, SAP %d\n", scene_name, n, when, t->count, s->count);
        for (i = 0; i < t->count && shown < 5; ++i)
            if (!bsearch(&t->pairs[i], s->pairs, (size_t)s->count, sizeof *s->pairs, cmp_u64)) {
                fprintf(stderr, "  only in tree: (%d, %d)\n", (int)(t->pairs[i] >> 32), (int)(uint32_t)t->pairs[i]);
                ++shown;
            }
        for (i = 0; i < s->count && shown < 10; ++i)
            if (!bsearch(&s->pairs[i], t->pairs, (size_t)t->count, sizeof *t->pairs, cmp_u64)) {
                fprintf(stderr, "  only in SAP: (%d, %d)\n", (int)(s->pairs[i] >> 32), (int)(uint32_t)s->pairs[i]);
                ++shown;
            }
        exit(1);
    }
    if (t->began != s->began || t->ended != s->ended || t->refits != s->refits) {
        fprintf(stderr, "bench_collision: %s n=%d %s: began/ended/refits differ: tree %lld/%lld/%lld, SAP %lld/%lld/%lld\n",
                scene_name, n, when, t->began, t->ended, t->refits, s->began, s->ended, s->refits);
        exit(1);
    }
}

/* Both structures in lockstep on one run of the scene, compared at the
   start and every `every` steps. */
static int validate_lockstep(scene *sc, const char *name, int steps, int every)
{
    tree_bp tb;
    sap_bp sb;
    bp_result tr, sr;
    int step, checks = 0;
    scene_reset(sc);
    tree_build(&tb, sc);
    sap_build(&sb, sc);
    for (step = 0; step <= steps; ++step) {
        if (step > 0) {
            scene_advance(sc);
            tree_step(&tb);
            sap_step(&sb);
        }
        if (step % every == 0) {
            char when[64];
            sprintf(when, "lockstep step %d", step);
            tree_result(&tb, &tr);
            sap_result(&sb, &sr);
            check_same(&tr, &sr, name, sc->n, when);
            free(tr.pairs);
            free(sr.pairs);
            ++checks;
        }
    }
    tree_free(&tb);
    sap_free(&sb);
    return checks;
}

/* ------------------------------------------------------------- timed runs */
#define MAX_RUNS 32

typedef struct bp_timing {
    double ms[MAX_RUNS];   /* ms per step, per run */
    double med, min;
    double pairs;          /* mean pair-set size per timed step */
    double churn;          /* began + ended per step */
    double refits;         /* proxies refitted per step */
} bp_timing;

/* One run of one structure: reset, build, warm up, time `steps` steps. */
static double run_tree(scene *sc, int steps, bp_result *res, double *pairs_sum, tree_stats *st)
{
    tree_bp tb;
    double total = 0;
    int k;
    long long refits0, began0, ended0;
    scene_reset(sc);
    tree_build(&tb, sc);
    for (k = 0; k < WARMUP; ++k) {
        scene_advance(sc);
        tree_step(&tb);
    }
    refits0 = tb.refits;
    began0 = tb.began;
    ended0 = tb.ended;
    *pairs_sum = 0;
    for (k = 0; k < steps; ++k) {
        double t0, t1;
        scene_advance(sc);
        t0 = now_s();
        tree_step(&tb);
        t1 = now_s();
        total += t1 - t0;
        *pairs_sum += tb.list_count;
    }
    tree_result(&tb, res);
    res->refits -= refits0;
    res->began -= began0;
    res->ended -= ended0;
    if (st) tree_stats_of(&tb, st);
    tree_free(&tb);
    return 1e3 * total / steps;
}

static double run_sap(scene *sc, int steps, bp_result *res, double *pairs_sum)
{
    sap_bp sb;
    double total = 0;
    int k;
    long long refits0, began0, ended0;
    scene_reset(sc);
    sap_build(&sb, sc);
    for (k = 0; k < WARMUP; ++k) {
        scene_advance(sc);
        sap_step(&sb);
    }
    refits0 = sb.refits;
    began0 = sb.began;
    ended0 = sb.ended;
    *pairs_sum = 0;
    for (k = 0; k < steps; ++k) {
        double t0, t1;
        scene_advance(sc);
        t0 = now_s();
        sap_step(&sb);
        t1 = now_s();
        total += t1 - t0;
        *pairs_sum += sb.cur_count;
    }
    sap_result(&sb, res);
    res->refits -= refits0;
    res->began -= began0;
    res->ended -= ended0;
    sap_free(&sb);
    return 1e3 * total / steps;
}

/* ------------------------------------------------------------- narrowphase */
typedef struct np_timing { int n, pairs, touching; double ns_med, ns_min; } np_timing;

static void time_narrowphase(const scene *sc, const uint64_t *pairs, int count, int runs, np_timing *out)
{
    ga2d_transform *xf = (ga2d_transform *)xmalloc((size_t)sc->n * sizeof *xf);
    double ns[MAX_RUNS];
    int r, k, i, touching = 0;
    for (i = 0; i < sc->n; ++i) xf[i] = ga2d_transform_make(sc->p[i], sc->q[i]);
    for (r = 0; r < runs; ++r) {
        double t0, t1;
        touching = 0;
        t0 = now_s();
        for (k = 0; k < count; ++k) {
            int a = (int)(pairs[k] >> 32), b = (int)(uint32_t)pairs[k];
            ga2d_manifold m;
            int c = ga2d_collide_polygons(&sc->poly[a], xf[a], &sc->poly[b], xf[b], &m);
            if (c < 0) {
                fprintf(stderr, "bench_collision: ga2d_collide_polygons failed (%d)\n", c);
                exit(1);
            }
            touching += c > 0;
        }
        t1 = now_s();
        ns[r] = 1e9 * (t1 - t0) / (count ? count : 1);
    }
    out->n = sc->n;
    out->pairs = count;
    out->touching = touching;
    out->ns_med = median(ns, runs);
    out->ns_min = minimum(ns, runs);
    free(xf);
}

/* ------------------------------------------------------ full world step */
typedef struct world_timing { int n; double ms_med, ms_min; int pairs, touching; } world_timing;

static void time_world(const scene *sc, int runs, int steps, world_timing *out)
{
    double ms[MAX_RUNS];
    int r, k, i;
    ga2d_world_counters c;
    memset(&c, 0, sizeof c);
    for (r = 0; r < runs; ++r) {
        ga2d_world_def wd = ga2d_default_world_def();
        ga2d_world *w;
        double t0, t1;
        wd.gravity = ga2d_vec_make(0, 0);
        wd.substeps = 1;
        w = ga2d_world_create(&wd);
        if (!w) exit(2);
        for (i = 0; i < sc->n; ++i) {
            ga2d_body_def bd = ga2d_default_body_def();
            bd.type = sc->is_static[i] ? GA2D_BODY_STATIC : GA2D_BODY_DYNAMIC;
            bd.position = sc->p0[i];
            bd.rotor = sc->q[i];
            bd.velocity = sc->v[i];
            bd.polygon = sc->poly[i];
            if (ga2d_body_id_is_null(ga2d_body_create(w, &bd))) {
                fprintf(stderr, "bench_collision: ga2d_body_create failed\n");
                exit(1);
            }
        }
        for (k = 0; k < WARMUP; ++k) ga2d_world_step(w, DT);
        t0 = now_s();
        for (k = 0; k < steps; ++k) ga2d_world_step(w, DT);
        t1 = now_s();
        ms[r] = 1e3 * (t1 - t0) / steps;
        c = ga2d_world_get_counters(w);
        ga2d_world_destroy(w);
    }
    out->n = sc->n;
    out->ms_med = median(ms, runs);
    out->ms_min = minimum(ms, runs);
    out->pairs = c.pair_count;
    out->touching = c.touching_count;
}

/* ------------------------------------------------------------------- main */
#define NSIZES 4
static const int sizes[NSIZES] = {100, 1000, 10000, 50000};

static int runs_for(int n) { return n <= 1000 ? 9 : n <= 10000 ? 7 : 5; }
static int steps_for(int n, int resting)
{
    if (n <= 100) return 1000;
    if (n <= 1000) return 300;
    if (n <= 10000) return 100;
    return resting ? 60 : 30;
}

int main(int argc, char **argv)
{
    static const char *scene_names[2] = {"moving", "resting"};
    bp_timing tt[2][NSIZES], st[2][NSIZES];
    tree_stats ts[2][NSIZES];
    np_timing np[NSIZES];
    world_timing wt[NSIZES];
    int np_count = 0, wt_count = 0, sci, si, r, checks = 0;
    double start = now_s();
    FILE *csv = NULL;

    if (argc > 1) {
        csv = fopen(argv[1], "w");
        if (!csv) {
            fprintf(stderr, "bench_collision: cannot write %s\n", argv[1]);
            return 2;
        }
    }
    printf("bench_collision: broadphase (header's AABB tree vs sort-and-sweep) and narrowphase\n");
    printf("real = %s, margin %.2f m, %.0f m^2 per body, %d%% static, speeds <= %.0f m/s, dt 1/60, warm-up %d steps\n",
           sizeof(ga2d_real) == sizeof(double) ? "double" : "float", (double)MARGIN, AREA_PER_BODY,
           (int)(100 * STATIC_FRACTION), MAX_SPEED, WARMUP);
    printf("ms/step: broadphase only (AABB of every moving body, refits, new and ended pairs); body motion not timed.\n");
    printf("runs alternate tree/SAP from the same start state; med = median over runs, min = fastest run.\n\n");
    printf("%-8s %6s %4s %5s | %9s %9s | %9s %9s | %7s | %8s %8s %7s | %8s %8s\n", "scene", "n", "runs", "steps",
           "tree med", "tree min", "SAP med", "SAP min", "SAP/tr", "pairs", "churn", "refits", "tree Mp/s", "SAP Mp/s");
    fflush(stdout);

    for (sci = 0; sci < 2; ++sci) {
        for (si = 0; si < NSIZES; ++si) {
            scene sc;
            int n = sizes[si], runs = runs_for(n), steps = steps_for(n, sci);
            bp_timing *T = &tt[sci][si], *S = &st[sci][si];
            double ratio;
            bp_result last_sap;
            memset(&last_sap, 0, sizeof last_sap);
            scene_init(&sc, n, sci);
            /* start state (both) and, in the small sizes, every 50 steps */
            checks += validate_lockstep(&sc, scene_names[sci], n <= 1000 ? 200 : 0, 50);
            memset(T, 0, sizeof *T);
            memset(S, 0, sizeof *S);
            for (r = 0; r < runs; ++r) {
                bp_result tr, sr;
                double tp, sp;
                char when[64];
                /* alternate which goes first */
                if (r % 2 == 0) {
                    T->ms[r] = run_tree(&sc, steps, &tr, &tp, r == runs - 1 ? &ts[sci][si] : NULL);
                    S->ms[r] = run_sap(&sc, steps, &sr, &sp);
                } else {
                    S->ms[r] = run_sap(&sc, steps, &sr, &sp);
                    T->ms[r] = run_tree(&sc, steps, &tr, &tp, r == runs - 1 ? &ts[sci][si] : NULL);
                }
                /* same workload: the same pair set and the same churn */
                sprintf(when, "end of run %d", r);
                check_same(&tr, &sr, scene_names[sci], n, when);
                ++checks;
                T->pairs = S->pairs = tp / steps;
                T->churn = S->churn = (double)(tr.began + tr.ended) / steps;
                T->refits = S->refits = (double)tr.refits / steps;
                free(tr.pairs);
                free(last_sap.pairs);
                last_sap = sr;
            }
            T->med = median(T->ms, runs);
            T->min = minimum(T->ms, runs);
            S->med = median(S->ms, runs);
            S->min = minimum(S->ms, runs);
            ratio = S->med / T->med;
            printf("%-8s %6d %4d %5d | %9.4f %9.4f | %9.4f %9.4f | %7.2f | %8.0f %8.1f %7.1f | %8.2f %8.2f\n",
                   scene_names[sci], n, runs, steps, T->med, T->min, S->med, S->min, ratio, T->pairs, T->churn, T->refits,
                   T->pairs / T->med * 1e-3, S->pairs / S->med * 1e-3);
            fflush(stdout);
            if (csv) {
                if (sci == 0 && si == 0)
                    fprintf(csv, "section,scene,n,structure,runs,steps,median_ms_per_step,min_ms_per_step,pairs_per_step,"
                                 "churn_per_step,refits_per_step,pairs_per_s,ratio_vs_tree,ns_per_pair,touching\n");
                fprintf(csv, "broadphase,%s,%d,tree,%d,%d,%.6f,%.6f,%.1f,%.2f,%.2f,%.4g,1,,\n", scene_names[sci], n, runs,
                        steps, T->med, T->min, T->pairs, T->churn, T->refits, T->pairs / T->med * 1e3);
                fprintf(csv, "broadphase,%s,%d,sap,%d,%d,%.6f,%.6f,%.1f,%.2f,%.2f,%.4g,%.4f,,\n", scene_names[sci], n, runs,
                        steps, S->med, S->min, S->pairs, S->churn, S->refits, S->pairs / S->med * 1e3, ratio);
            }
            /* the narrowphase over the moving scene's pairs (positions: the
               end of the last run, which both structures reached) */
            if (sci == 0 && n >= 1000) {
                time_narrowphase(&sc, last_sap.pairs, last_sap.count, 5, &np[np_count++]);
                time_world(&sc, 5, n >= 50000 ? 20 : n >= 10000 ? 50 : 200, &wt[wt_count++]);
            }
            free(last_sap.pairs);
            scene_free(&sc);
        }
    }

    printf("\ncost growth: (ms/step / n) relative to n = 1000 (1.00 = linear in n)\n");
    printf("%-8s %-5s", "scene", "");
    for (si = 0; si < NSIZES; ++si) printf(" %9d", sizes[si]);
    printf("\n");
    for (sci = 0; sci < 2; ++sci) {
        int which;
        for (which = 0; which < 2; ++which) {
            const bp_timing *X = which ? st[sci] : tt[sci];
            printf("%-8s %-5s", scene_names[sci], which ? "SAP" : "tree");
            for (si = 0; si < NSIZES; ++si) printf(" %9.2f", (X[si].med / sizes[si]) / (X[1].med / sizes[1]));
            printf("\n");
        }
    }

    printf("\ntree diagnostics (moving tree, end of the last run): height vs log2(leaves), nodes visited per\n"
           "query of a moving proxy's fat box, leaves hit per query, SAH = sum of inner perimeters / root perimeter\n");
    printf("%-8s %6s %7s %6s %7s %9s %7s %9s\n", "scene", "n", "leaves", "height", "log2", "visits/q", "hits/q", "SAH");
    for (sci = 0; sci < 2; ++sci)
        for (si = 0; si < NSIZES; ++si) {
            const tree_stats *x = &ts[sci][si];
            printf("%-8s %6d %7d %6d %7.1f %9.1f %7.2f %9.1f\n", scene_names[sci], sizes[si], x->leaves, x->height,
                   log((double)x->leaves) / log(2.0), x->visits, x->hits, x->sah);
        }

    printf("\nnarrowphase alone: ga2d_collide_polygons over the moving scene's pair set (median of 5)\n");
    printf("%6s %8s %9s %9s %9s %12s %14s\n", "n", "pairs", "touching", "ns/pair", "min", "Mpairs/s", "Mmanifolds/s");
    for (si = 0; si < np_count; ++si) {
        const np_timing *x = &np[si];
        printf("%6d %8d %9d %9.1f %9.1f %12.2f %14.2f\n", x->n, x->pairs, x->touching, x->ns_med, x->ns_min,
               1e3 / x->ns_med, 1e3 / x->ns_med * x->touching / (x->pairs ? x->pairs : 1));
        if (csv)
            fprintf(csv, "narrowphase,moving,%d,collide_polygons,5,1,%.6f,%.6f,%d,,,%.4g,,%.2f,%d\n", x->n,
                    x->ns_med * x->pairs * 1e-6, x->ns_min * x->pairs * 1e-6, x->pairs, 1e9 / x->ns_med, x->ns_med,
                    x->touching);
    }
    printf("(Mmanifolds/s counts manifolds with points; every pair gets a call.)\n");

    printf("\nfull ga2d_world_step, moving scene (gravity 0, 1 substep, no wrap; median of 5) vs the tree broadphase alone\n");
    printf("%6s %10s %10s %8s %9s %12s\n", "n", "ms/step", "min", "pairs", "touching", "bp share");
    for (si = 0; si < wt_count; ++si) {
        const world_timing *x = &wt[si];
        printf("%6d %10.4f %10.4f %8d %9d %11.0f%%\n", x->n, x->ms_med, x->ms_min, x->pairs, x->touching,
               100 * tt[0][si + 1].med / x->ms_med);
        if (csv)
            fprintf(csv, "world_step,moving,%d,world,5,,%.6f,%.6f,%d,,,,,,%d\n", x->n, x->ms_med, x->ms_min, x->pairs,
                    x->touching);
    }
    printf("\n%d pair-set checks passed (tree == SAP); total %.1f s\n", checks, now_s() - start);
    if (csv) fclose(csv);
    return 0;
}
