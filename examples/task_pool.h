/* task_pool.h - a small pthread task system for ga2d_world_def's
   enqueue_task / finish_task (DESIGN §13): copy it, or plug in your own.

       task_pool *pool = task_pool_create(2);      // the caller + 1 thread
       ga2d_world_def wd = ga2d_default_world_def();
       wd.worker_count = task_pool_workers(pool);
       wd.enqueue_task = task_pool_enqueue;
       wd.finish_task = task_pool_finish;
       wd.user_task_context = pool;
       ...
       ga2d_world_destroy(w);
       task_pool_destroy(pool);

   The pool keeps worker_count - 1 threads waiting; the thread that steps
   the world is worker 0 and works too, in task_pool_finish.  A job's
   items are shared out in order, worker w taking the w-th of worker_count
   equal shares, a range (at least min_range items, a quarter of a share)
   at a time; a worker done with its own share takes ranges of the
   others'.  So a worker gets the same items in every job over the same
   count: a world's passes over its colours then find their bodies and
   constraints in the cache of the core that touched them last (handed out
   first come, first served, two workers stepped large_pyramid no faster
   than one).  One job at a time (a ga2d step enqueues a stage and
   finishes it before the next); one world per pool at a time.  Idle
   workers spin a while before they sleep (jobs come microseconds apart
   while a world steps): a pool costs its threads' cores while a world is
   stepping, and a moment after.

   Another job system (enkiTS, a game's own) plugs in the same way: its
   enqueue runs task(start, end, worker, task_context) over ranges that
   cover [0, item_count) exactly once, with worker < worker_count and no
   two running ranges sharing a worker index, and returns a handle its
   finish waits on (or runs them all at once and returns NULL).  ga2d's
   results do not depend on how the ranges are cut or ordered.

   Header-only: define TASK_POOL_IMPLEMENTATION in one file (it needs
   -pthread, and gcc's or clang's atomics). */
#ifndef TASK_POOL_H
#define TASK_POOL_H

#include "ga2d_physics.h"

typedef struct task_pool task_pool;

/* NULL on failure (no memory, or a thread could not start). */
task_pool *task_pool_create(int worker_count);
void task_pool_destroy(task_pool *pool);
int task_pool_workers(const task_pool *pool);
void *task_pool_enqueue(ga2d_task_fn *task, int item_count, int min_range, void *task_context, void *user_context);
void task_pool_finish(void *user_task, void *user_context);

#endif

#ifdef TASK_POOL_IMPLEMENTATION
#include <pthread.h>
#include <sched.h>
#include <stdint.h>
#include <stdlib.h>

#define TASK_POOL_RANGES_PER_WORKER 4
/* A step hands over a few dozen short jobs (a stage over the bodies, a
   substep's solver passes), some of them a few microseconds: a worker
   waiting on a condition variable takes about as long to wake.  So an idle worker first spins on the job word,
   pausing, then yields its core (more workers than cores), and only then
   sleeps until the next job. */
#ifndef TASK_POOL_SPINS
#define TASK_POOL_SPINS 2000  /* polls with a pause between */
#endif
#ifndef TASK_POOL_YIELDS
#define TASK_POOL_YIELDS 200  /* then polls with a yield between */
#endif

/* The compiler's atomics (gcc, clang); another compiler brings its own. */
#define TASK_POOL_LOAD(x) __atomic_load_n(&(x), __ATOMIC_ACQUIRE)
#define TASK_POOL_STORE(x, v) __atomic_store_n(&(x), (v), __ATOMIC_RELEASE)
#define TASK_POOL_ADD(x, v) __atomic_add_fetch(&(x), (v), __ATOMIC_ACQ_REL)
#define TASK_POOL_CAS(x, old, new) __atomic_compare_exchange_n(&(x), &(old), (new), 0, __ATOMIC_ACQ_REL, __ATOMIC_ACQUIRE)
#if defined(__x86_64__) || defined(__i386__)
#define TASK_POOL_PAUSE() __builtin_ia32_pause()
#else
#define TASK_POOL_PAUSE() ((void)0)
#endif

typedef struct task_pool_thread {
    task_pool *pool;
    int index;
    pthread_t thread;
} task_pool_thread;

struct task_pool {
    pthread_mutex_t lock;
    pthread_cond_t wake;
    task_pool_thread *threads;
    int workers, started;
    int quit, sleepers;
    /* the job under way: `state` is its generation (high 32 bits) and 1
       while the job's fields are being written; each worker's cursor the
       same generation and the next item of its share to hand out (low
       32), so a worker that read an old job's fields claims nothing of a
       new one */
    ga2d_task_fn *task;
    void *context;
    int count, range, done;
    uint64_t state;
    uint64_t *cursors;  /* TASK_POOL_STRIDE apart: one cache line each */
};
#define TASK_POOL_STRIDE 8

/* Where worker w's share of count items begins. */
static int task_pool__share(const task_pool *p, int count, int w)
{
    return (int)((long long)count * w / p->workers);
}

/* Claims the next range of `owner`'s share of job gen, or returns 0 (all
   handed out, or the job is no longer gen). */
static int task_pool__take(task_pool *p, uint32_t gen, int owner, int count, int range, int *start, int *end)
{
    uint64_t *cursor = &p->cursors[owner * TASK_POOL_STRIDE];
    uint64_t v = TASK_POOL_LOAD(*cursor);
    int limit = task_pool__share(p, count, owner + 1);
    for (;;) {
        int next = (int)(uint32_t)v;
        if ((uint32_t)(v >> 32) != gen || next >= limit) return 0;
        *start = next;
        *end = limit - next > range ? next + range : limit;
        if (TASK_POOL_CAS(*cursor, v, ((uint64_t)gen << 32) | (uint32_t)*end)) return 1;
    }
}

/* Runs ranges of job gen, its own share first, until none is left.  The
   fields are read, then the state again: a worker late for job gen may
   find the next job's being written (its own share already done by the
   others), and must not claim gen's ranges with that job's count. */
static void task_pool__work(task_pool *p, uint32_t gen, int worker)
{
    ga2d_task_fn *task = (ga2d_task_fn *)TASK_POOL_LOAD(p->task);
    void *context = TASK_POOL_LOAD(p->context);
    int count = TASK_POOL_LOAD(p->count), range = TASK_POOL_LOAD(p->range), start, end, k;
    if (TASK_POOL_LOAD(p->state) != (uint64_t)gen << 32) return;
    for (k = 0; k < p->workers; ++k) {
        int owner = (worker + k) % p->workers;
        while (task_pool__take(p, gen, owner, count, range, &start, &end)) {
            task(start, end, worker, context);
            TASK_POOL_ADD(p->done, end - start);
        }
    }
}

/* Whether state holds a posted job other than `seen`. */
static int task_pool__posted(uint64_t state, uint32_t seen) { return (uint32_t)(state >> 32) != seen && !(state & 1); }

/* Waits for a posted job other than `seen` (or quit): its generation. */
static uint32_t task_pool__wait(task_pool *p, uint32_t seen)
{
    uint64_t state;
    int i;
    for (i = 0; i < TASK_POOL_SPINS + TASK_POOL_YIELDS; ++i) {
        state = TASK_POOL_LOAD(p->state);
        if (task_pool__posted(state, seen) || TASK_POOL_LOAD(p->quit)) return (uint32_t)(state >> 32);
        if (i < TASK_POOL_SPINS) TASK_POOL_PAUSE();
        else sched_yield();
    }
    pthread_mutex_lock(&p->lock);
    __atomic_add_fetch(&p->sleepers, 1, __ATOMIC_SEQ_CST);
    while (!task_pool__posted(__atomic_load_n(&p->state, __ATOMIC_SEQ_CST), seen) && !TASK_POOL_LOAD(p->quit))
        pthread_cond_wait(&p->wake, &p->lock);
    __atomic_sub_fetch(&p->sleepers, 1, __ATOMIC_SEQ_CST);
    pthread_mutex_unlock(&p->lock);
    return (uint32_t)(TASK_POOL_LOAD(p->state) >> 32);
}

static void *task_pool__main(void *arg)
{
    task_pool_thread *t = (task_pool_thread *)arg;
    task_pool *p = t->pool;
    uint32_t seen = 0;
    for (;;) {
        seen = task_pool__wait(p, seen);
        if (TASK_POOL_LOAD(p->quit)) break;
        task_pool__work(p, seen, t->index);
    }
    return NULL;
}

task_pool *task_pool_create(int worker_count)
{
    task_pool *p = (task_pool *)calloc(1, sizeof *p);
    int i;
    if (!p) return NULL;
    p->workers = worker_count < 1 ? 1 : worker_count;
    pthread_mutex_init(&p->lock, NULL);
    pthread_cond_init(&p->wake, NULL);
    p->threads = (task_pool_thread *)calloc((size_t)p->workers, sizeof *p->threads);
    p->cursors = (uint64_t *)calloc((size_t)p->workers * TASK_POOL_STRIDE, sizeof *p->cursors);
    if (!p->threads || !p->cursors) {
        task_pool_destroy(p);
        return NULL;
    }
    for (i = 1; i < p->workers; ++i) {
        p->threads[i].pool = p;
        p->threads[i].index = i;
        if (pthread_create(&p->threads[i].thread, NULL, task_pool__main, &p->threads[i]) != 0) {
            task_pool_destroy(p);
            return NULL;
        }
        p->started = i;
    }
    return p;
}

void task_pool_destroy(task_pool *pool)
{
    int i;
    if (!pool) return;
    pthread_mutex_lock(&pool->lock);
    TASK_POOL_STORE(pool->quit, 1);
    pthread_cond_broadcast(&pool->wake);
    pthread_mutex_unlock(&pool->lock);
    for (i = 1; i <= pool->started; ++i) pthread_join(pool->threads[i].thread, NULL);
    pthread_cond_destroy(&pool->wake);
    pthread_mutex_destroy(&pool->lock);
    free(pool->threads);
    free(pool->cursors);
    free(pool);
}

int task_pool_workers(const task_pool *pool) { return pool ? pool->workers : 1; }

void *task_pool_enqueue(ga2d_task_fn *task, int item_count, int min_range, void *task_context, void *user_context)
{
    task_pool *p = (task_pool *)user_context;
    int range = item_count / (p->workers * TASK_POOL_RANGES_PER_WORKER), w;
    uint32_t gen;
    if (range < min_range) range = min_range;
    if (range < 1) range = 1;
    if (p->workers == 1 || item_count <= range) { /* one range: run it here */
        task(0, item_count, 0, task_context);
        return NULL;
    }
    /* the last job is finished (one at a time): no worker holds a range */
    gen = (uint32_t)(TASK_POOL_LOAD(p->state) >> 32) + 1;
    __atomic_store_n(&p->state, ((uint64_t)gen << 32) | 1, __ATOMIC_SEQ_CST); /* being written */
    TASK_POOL_STORE(p->task, task);
    TASK_POOL_STORE(p->context, task_context);
    TASK_POOL_STORE(p->count, item_count);
    TASK_POOL_STORE(p->range, range);
    TASK_POOL_STORE(p->done, 0);
    for (w = 0; w < p->workers; ++w)
        TASK_POOL_STORE(p->cursors[w * TASK_POOL_STRIDE], ((uint64_t)gen << 32) | (uint32_t)task_pool__share(p, item_count, w));
    __atomic_store_n(&p->state, (uint64_t)gen << 32, __ATOMIC_SEQ_CST);
    if (__atomic_load_n(&p->sleepers, __ATOMIC_SEQ_CST) > 0) {
        pthread_mutex_lock(&p->lock);
        pthread_cond_broadcast(&p->wake);
        pthread_mutex_unlock(&p->lock);
    }
    return p;
}

void task_pool_finish(void *user_task, void *user_context)
{
    task_pool *p = (task_pool *)user_context;
    uint32_t gen = (uint32_t)(TASK_POOL_LOAD(p->state) >> 32);
    int count = TASK_POOL_LOAD(p->count), i = 0;
    (void)user_task;
    task_pool__work(p, gen, 0); /* the caller is worker 0 */
    while (TASK_POOL_LOAD(p->done) < count)
        if (++i < TASK_POOL_SPINS) TASK_POOL_PAUSE();
        else sched_yield();
}
#endif
