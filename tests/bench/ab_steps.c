/* ab_steps.c - two builds of ga2d_physics.h, step by step (ab_header.sh
   builds and runs it; see ab_world.h).

   For each scene and round, a world of each build is made from the same
   scene, and the two are stepped in turn, one step each, the build that
   goes first swapped every step: a slow spell of a busy machine then falls
   on both alike, however short.  Only ga2d_world_step is timed, the first
   10 steps of a round left out.  Prints per round the ms per step of each
   build; then the medians over the rounds, the median over the rounds of
   new / old, and the median of new / old over every timed step of every
   round (each a pair stepped microseconds apart).  The two builds'
   figures must agree bit for bit when the change between them keeps the
   scene's bits; they are printed, and compared.

     ab_steps ROUNDS scene ...

   Exit status 0 when every world was built and stepped. */
#define _POSIX_C_SOURCE 199309L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "ab_world.h"

#define WARMUP 10
#define MAX_ROUNDS 64

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Median of v[0..n-1] (sorts v). */
static double median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, cmp_double);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/* One scene, `rounds` rounds, its table row written to row; 0 when every
   step went well. */
static int run_scene(const char *scene, int rounds, char *row, size_t size)
{
    double old_ms[MAX_ROUNDS], new_ms[MAX_ROUNDS], ratio[MAX_ROUNDS], *pairs = NULL, old_fig = 0, new_fig = 0;
    char fig_name[64] = "";
    int r, k, n_pairs = 0, same = 1;
    if (ab_old_holds(scene) == 0) {
        printf("  %-14s skipped: its bodies come and go, or it has a chain (the runs measure covers it)\n", scene);
        snprintf(row, size, "| %s | - | - | - | - | not stepped in turn: bodies come and go, or a chain |\n", scene);
        return 0;
    }
    for (r = 0; r < rounds; ++r) {
        ab_world *o = ab_old_make(scene), *n = ab_new_make(scene);
        double to = 0, tn = 0, so = 0, sn = 0;
        int steps;
        if (!o || !n) {
            fprintf(stderr, "ab_steps: cannot make %s\n", scene);
            ab_old_free(o);
            ab_new_free(n);
            free(pairs);
            return 1;
        }
        steps = ab_old_steps(o);
        if (!pairs) pairs = (double *)malloc((size_t)rounds * (size_t)steps * sizeof *pairs);
        if (!pairs) return 1;
        for (k = 0; k < steps; ++k) {
            if ((k + r) % 2 == 0) {
                to = ab_old_step(o);
                tn = ab_new_step(n);
            } else {
                tn = ab_new_step(n);
                to = ab_old_step(o);
            }
            if (to < 0 || tn < 0) {
                fprintf(stderr, "ab_steps: %s: step %d failed (%s)\n", scene, k, to < 0 ? "old" : "new");
                ab_old_free(o);
                ab_new_free(n);
                free(pairs);
                return 1;
            }
            if (k < WARMUP) continue;
            so += to;
            sn += tn;
            if (to > 0) pairs[n_pairs++] = tn / to;
        }
        old_ms[r] = so / (steps - WARMUP);
        new_ms[r] = sn / (steps - WARMUP);
        ratio[r] = new_ms[r] / old_ms[r];
        if (r == 0) {
            snprintf(fig_name, sizeof fig_name, "%s", ab_old_figure_name(o));
            old_fig = ab_old_figure(o);
            new_fig = ab_new_figure(n);
        }
        same = same && memcmp(&old_fig, &new_fig, sizeof old_fig) == 0 && ab_old_figure(o) == old_fig &&
               ab_new_figure(n) == new_fig;
        printf("  %-14s round %d: old %8.3f  new %8.3f ms/step  new/old %.3f\n", scene, r + 1, old_ms[r], new_ms[r],
               ratio[r]);
        fflush(stdout);
        ab_old_free(o);
        ab_new_free(n);
    }
    {
        double mo = median(old_ms, rounds), mn = median(new_ms, rounds), mr = median(ratio, rounds);
        double mp = median(pairs, n_pairs);
        snprintf(row, size, "| %s | %.3f | %.3f | %.3f | %.3f | %s: %s (%.9g / %.9g) |\n", scene, mo, mn, mr,
                 mp, fig_name, same ? "the same bits" : "DIFFER", old_fig, new_fig);
    }
    free(pairs);
    return 0;
}

int main(int argc, char **argv)
{
    static char rows[16][512];
    int rounds = argc > 1 ? atoi(argv[1]) : 0, i, bad = 0;
    if (rounds < 1 || rounds > MAX_ROUNDS || argc < 3 || argc > 18) {
        fprintf(stderr, "usage: ab_steps ROUNDS scene ...   (1 <= ROUNDS <= %d, at most 16 scenes)\n", MAX_ROUNDS);
        return 2;
    }
    printf("ab_steps: %d rounds, old and new stepped in turn (the first swapped every step)\n", rounds);
    for (i = 2; i < argc; ++i) bad |= run_scene(argv[i], rounds, rows[i - 2], sizeof rows[i - 2]);
    printf("\n| scene | old ms/step (median of rounds) | new ms/step | new / old (median of rounds) | new / old "
           "(median of step pairs) | figures (old / new) |\n|---|---|---|---|---|---|\n");
    for (i = 2; i < argc; ++i) fputs(rows[i - 2], stdout);
    return bad;
}
