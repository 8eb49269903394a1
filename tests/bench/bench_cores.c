/* bench_cores.c - what a second worker can give on this machine, apart
   from ga2d: the 2-worker rows of bench_scenes and bench-peers read
   against it.

   Three kinds of work, each run by one thread and then by two threads at
   once (each the same work as the one): the scaling is 2 x one's time /
   two's time (2 when the second core is a whole core):
     fp      eight independent multiply-add chains (the cores' arithmetic)
     stream  sums over a 64 MiB array (memory bandwidth)
     chase   a random walk over a 256 KiB table (a core's own caches)
   And the price of sharing: one cache line passed from one thread to the
   other and back, in ns a round trip.  A step split over workers moves
   the lines of bodies and constraints from the core that wrote them to
   the one that reads them next, at half that each: where it is hundreds
   of ns (cores far apart, as in a virtual machine's vCPUs on different
   dies), light stages cost more split than whole, for any engine.

   Medians over ROUNDS rounds.  Writes measure,value rows to the CSV given.

     bench_cores [out.csv] */
#define _POSIX_C_SOURCE 200112L
#include <pthread.h>
#include <sched.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#define ROUNDS 5
#define FP_ITERATIONS 50000000L
#define STREAM_DOUBLES ((size_t)1 << 23) /* 64 MiB */
#define STREAM_SWEEPS 8
#define CHASE_SLOTS ((size_t)1 << 16)    /* 256 KiB of unsigned */
#define CHASE_STEPS 40000000L
#define ROUND_TRIPS 200000
#define SPINS_BEFORE_YIELD 100000        /* both threads on one core: let the other run */

static double now_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

static volatile double sink; /* keeps the work from being optimised away */

static void *work_fp(void *unused)
{
    double a[8];
    long i;
    int k;
    (void)unused;
    for (k = 0; k < 8; ++k) a[k] = k + 1;
    for (i = 0; i < FP_ITERATIONS; ++i)
        for (k = 0; k < 8; ++k) a[k] = a[k] * 0.9999999 + 1e-7;
    for (k = 0; k < 8; ++k) sink += a[k];
    return NULL;
}

static void *work_stream(void *unused)
{
    double *x = (double *)malloc(STREAM_DOUBLES * sizeof *x), s = 0;
    size_t i;
    int r;
    (void)unused;
    if (!x) return (void *)1;
    for (i = 0; i < STREAM_DOUBLES; ++i) x[i] = (double)i;
    for (r = 0; r < STREAM_SWEEPS; ++r)
        for (i = 0; i < STREAM_DOUBLES; ++i) s += x[i];
    sink += s;
    free(x);
    return NULL;
}

static void *work_chase(void *unused)
{
    unsigned *next = (unsigned *)malloc(CHASE_SLOTS * sizeof *next), j = 0;
    size_t i;
    long r;
    (void)unused;
    if (!next) return (void *)1;
    for (i = 0; i < CHASE_SLOTS; ++i) next[i] = (unsigned)((i * 2654435761u) % CHASE_SLOTS);
    for (r = 0; r < CHASE_STEPS; ++r) j = next[j] ^ (unsigned)(r & 1);
    sink += j;
    free(next);
    return NULL;
}

/* 2 x one thread's time over two threads' time; < 0 when a thread failed */
static double scaling(void *(*work)(void *))
{
    pthread_t a, b;
    void *ra = NULL, *rb = NULL, *r1;
    double t0 = now_s(), t1, t2;
    r1 = work(NULL);
    t1 = now_s();
    if (r1 || pthread_create(&a, NULL, work, NULL) != 0) return -1;
    if (pthread_create(&b, NULL, work, NULL) != 0) {
        pthread_join(a, NULL);
        return -1;
    }
    pthread_join(a, &ra);
    pthread_join(b, &rb);
    t2 = now_s();
    return ra || rb ? -1 : 2 * (t1 - t0) / (t2 - t1);
}

static int ball __attribute__((aligned(64))); /* the line passed to and fro: odd, the other thread's turn */

static void wait_for(int value)
{
    long spins = 0;
    while (__atomic_load_n(&ball, __ATOMIC_ACQUIRE) != value)
        if (++spins % SPINS_BEFORE_YIELD == 0) sched_yield();
}

static void *returner(void *unused)
{
    int i;
    (void)unused;
    for (i = 0; i < ROUND_TRIPS; ++i) {
        wait_for(2 * i + 1);
        __atomic_store_n(&ball, 2 * i + 2, __ATOMIC_RELEASE);
    }
    return NULL;
}

/* ns per round trip of one cache line; < 0 when the thread failed */
static double round_trip_ns(void)
{
    pthread_t t;
    double t0, t1;
    int i;
    __atomic_store_n(&ball, 0, __ATOMIC_RELEASE);
    if (pthread_create(&t, NULL, returner, NULL) != 0) return -1;
    t0 = now_s();
    for (i = 0; i < ROUND_TRIPS; ++i) {
        __atomic_store_n(&ball, 2 * i + 1, __ATOMIC_RELEASE);
        wait_for(2 * i + 2);
    }
    t1 = now_s();
    pthread_join(t, NULL);
    return (t1 - t0) / ROUND_TRIPS * 1e9;
}

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, by_value);
    return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

int main(int argc, char **argv)
{
    static const char *names[] = {"fp", "stream", "chase"};
    static const char *what[] = {"eight multiply-add chains", "sums over 64 MiB", "a walk over 256 KiB"};
    void *(*works[])(void *) = {work_fp, work_stream, work_chase};
    double result[4], v[ROUNDS];
    FILE *csv = NULL;
    int i, r, ok = 1;
    printf("bench_cores: what a second worker can give here (%ld cores online): two threads against one,\n"
           "the same work each, medians of %d rounds\n",
           sysconf(_SC_NPROCESSORS_ONLN), ROUNDS);
    for (i = 0; i < 3; ++i) {
        for (r = 0; r < ROUNDS; ++r) v[r] = scaling(works[i]);
        result[i] = median(v, ROUNDS);
        ok &= v[0] > 0; /* sorted: the least */
        printf("  %-7s %-26s scaling %.2f\n", names[i], what[i], result[i]);
    }
    for (r = 0; r < ROUNDS; ++r) v[r] = round_trip_ns();
    result[3] = median(v, ROUNDS);
    ok &= v[0] > 0;
    printf("  a cache line passed to the other thread and back: %.0f ns (median of %d x %d round trips)\n", result[3],
           ROUNDS, ROUND_TRIPS);
    if (argc > 1) {
        csv = fopen(argv[1], "w");
        if (!csv) {
            fprintf(stderr, "bench_cores: cannot write %s\n", argv[1]);
            return 1;
        }
        fprintf(csv, "measure,value\n");
        for (i = 0; i < 3; ++i) fprintf(csv, "%s_scaling,%.3f\n", names[i], result[i]);
        fprintf(csv, "line_round_trip_ns,%.1f\n", result[3]);
        fclose(csv);
    }
    if (!ok) fprintf(stderr, "bench_cores: a thread could not start or allocate\n");
    return ok ? 0 : 1;
}
