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
   the world is worker 0 and works too, in task_pool_finish.  A job is cut
   into ranges of at least min_range items, about four per worker, handed
   out in order to whoever asks first.  One job at a time (a ga2d step
   enqueues a stage and finishes it before the next); one world per pool
   at a time.

   Another job system (enkiTS, a game's own) plugs in the same way: its
   enqueue runs task(start, end, worker, task_context) over ranges that
   cover [0, item_count) exactly once, with worker < worker_count and no
   two running ranges sharing a worker index, and returns a handle its
   finish waits on (or runs them all at once and returns NULL).  ga2d's
   results do not depend on how the ranges are cut or ordered.

   Header-only: define TASK_POOL_IMPLEMENTATION in one file (it needs
   -pthread). */
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
#include <stdlib.h>

#define TASK_POOL_RANGES_PER_WORKER 4

typedef struct task_pool_thread {
    task_pool *pool;
    int index;
    pthread_t thread;
} task_pool_thread;

struct task_pool {
    pthread_mutex_t lock;
    pthread_cond_t wake, done;
    task_pool_thread *threads;
    int workers, started, quit;
    /* the job under way */
    ga2d_task_fn *task;
    void *context;
    int count, range, next, running;
    unsigned long generation; /* a new job was posted */
};

/* Takes the next range of the job, or returns 0 (all handed out). */
static int task_pool__take(task_pool *p, int *start, int *end)
{
    if (!p->task || p->next >= p->count) return 0;
    *start = p->next;
    *end = p->count - p->next > p->range ? p->next + p->range : p->count;
    p->next = *end;
    ++p->running;
    return 1;
}

/* Runs ranges until none are left; called with the lock held, returns
   with it held. */
static void task_pool__work(task_pool *p, int worker)
{
    int start, end;
    while (task_pool__take(p, &start, &end)) {
        ga2d_task_fn *task = p->task;
        void *context = p->context;
        pthread_mutex_unlock(&p->lock);
        task(start, end, worker, context);
        pthread_mutex_lock(&p->lock);
        if (--p->running == 0 && p->next >= p->count) pthread_cond_broadcast(&p->done);
    }
}

static void *task_pool__main(void *arg)
{
    task_pool_thread *t = (task_pool_thread *)arg;
    task_pool *p = t->pool;
    unsigned long seen = 0;
    pthread_mutex_lock(&p->lock);
    for (;;) {
        while (!p->quit && p->generation == seen) pthread_cond_wait(&p->wake, &p->lock);
        if (p->quit) break;
        seen = p->generation;
        task_pool__work(p, t->index);
    }
    pthread_mutex_unlock(&p->lock);
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
    pthread_cond_init(&p->done, NULL);
    p->threads = (task_pool_thread *)calloc((size_t)p->workers, sizeof *p->threads);
    if (!p->threads) {
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
    pool->quit = 1;
    pthread_cond_broadcast(&pool->wake);
    pthread_mutex_unlock(&pool->lock);
    for (i = 1; i <= pool->started; ++i) pthread_join(pool->threads[i].thread, NULL);
    pthread_cond_destroy(&pool->done);
    pthread_cond_destroy(&pool->wake);
    pthread_mutex_destroy(&pool->lock);
    free(pool->threads);
    free(pool);
}

int task_pool_workers(const task_pool *pool) { return pool ? pool->workers : 1; }

void *task_pool_enqueue(ga2d_task_fn *task, int item_count, int min_range, void *task_context, void *user_context)
{
    task_pool *p = (task_pool *)user_context;
    int range = item_count / (p->workers * TASK_POOL_RANGES_PER_WORKER);
    if (range < min_range) range = min_range;
    if (range < 1) range = 1;
    if (p->workers == 1 || item_count <= range) { /* one range: run it here */
        task(0, item_count, 0, task_context);
        return NULL;
    }
    pthread_mutex_lock(&p->lock);
    p->task = task;
    p->context = task_context;
    p->count = item_count;
    p->range = range;
    p->next = 0;
    p->running = 0;
    ++p->generation;
    pthread_cond_broadcast(&p->wake);
    pthread_mutex_unlock(&p->lock);
    return p;
}

void task_pool_finish(void *user_task, void *user_context)
{
    task_pool *p = (task_pool *)user_context;
    (void)user_task;
    pthread_mutex_lock(&p->lock);
    task_pool__work(p, 0); /* the caller is worker 0 */
    while (p->running > 0 || p->next < p->count) pthread_cond_wait(&p->done, &p->lock);
    p->task = NULL;
    pthread_mutex_unlock(&p->lock);
}
#endif
