/* bench_scenes.c - the scenes of scenes.h in ga2d at its defaults, with
   each scene's accuracy figure, and the closed-form scenes of the solver
   and integrator issues (bounce, oscillator, spin, projectile).

   Every scene runs in a world from ga2d_default_world_def() (4 substeps,
   soft step, symplectic Euler, exact rotor update) with the scene's own
   gravity and sleep switch; bodies marked asleep are created asleep, and
   the tumbler's kinematic walls are given before every step the velocity
   that turns them about the pivot from where they are, and rain's and
   mixed_pile's bodies are made and destroyed between the steps the scene
   names (scene_run.h).

   Per scene: the bodies (the most alive at once), ms per step, the median
   and the minimum over the runs (BENCH_RUNS, default 3; the first 10
   steps of a run excluded; only ga2d_world_step timed), and the figure.
   ga2d is deterministic, so every run must give the same figure bit for
   bit: a run that does not is reported, as is a run that fails.
   Single-machine times: compare rows with each other.

   A constraint's cost: each scene's whole step over the constraints it
   solved (contacts and joints per timed step, from the counters), in µs
   per constraint.  When joint_grid (joints only) and large_pyramid
   (contacts only, about as many bodies, the same 4 substeps) both run,
   a last line and CSV row give µs per joint over µs per contact: the
   joints' goal is a ratio of at most 1.  joint_grid also prints its
   worst joint separation at the end.

     bench_scenes [out.csv [scene ...]]

   writes the CSV when given a path, and runs only the named scenes (of
   the table's names) when given any.  Exit status 0 when every scene ran
   and every run agreed.

   With a CSV path, each scenes.h scene also gets <scene>.csv beside it
   (make bench: build/bench/large_pyramid.csv, ...) in the form of Box2D
   v3's published benchmark results (its benchmark/<machine>/<scene>.csv,
   written by its benchmark/main.c): the line "threads,ms", then one line
   per worker count, "1,1234.5": the fastest run's time in ms of every step
   but the first, summed (Box2D's measure: its runs step the scene's steps
   and time all but the first; so do these, 500 for large_pyramid as
   there).  The worker counts are WORKER_COUNTS', one run of each in every
   round, taken in turn (the order reversed every other round): the
   2-worker line gives the ratio of the medians and the median of the
   rounds' ratios (bench_cores says what this machine's second core gave
   at the time). */
#define _POSIX_C_SOURCE 200112L
#define GA2D_IMPLEMENTATION
#include "ga2d_physics.h"
#define TASK_POOL_IMPLEMENTATION
#include "../../examples/task_pool.h"
#include "scenes.h"
#include "scene_run.h"

#define DEFAULT_RUNS 3
#define MAX_RUNS 64

/* The worker counts each scenes.h scene runs at (set_workers), the first
   the table's; each gets a line of the scene's threads,ms CSV. */
static const int WORKER_COUNTS[] = {1, 2};
#define WORKER_COUNT_N ((int)(sizeof WORKER_COUNTS / sizeof WORKER_COUNTS[0]))
#define MAX_PATH 1024

/* Sets the world def to step with `workers` workers; 0 when it cannot
   (the world def has no worker count yet: one worker, the calling
   thread's, is all there is). */
static int set_workers(ga2d_world_def *wd, int workers)
{
    static task_pool *pools[8];
    if (workers == 1) return 1;
    if (workers < 1 || workers > 8) return 0;
    if (!pools[workers - 1]) pools[workers - 1] = task_pool_create(workers); /* kept for the run's life */
    if (!pools[workers - 1]) return 0;
    wd->worker_count = workers;
    wd->enqueue_task = task_pool_enqueue;
    wd->finish_task = task_pool_finish;
    wd->user_task_context = pools[workers - 1];
    return 1;
}

/* Writes <dir>/<scene>.csv: "threads,ms" and a line per worker count of
   the least run_ms over its runs (ms[w][r], runs each); 0 when it cannot
   be written. */
static int write_threads_csv(const char *dir, const char *scene, const int *workers, int n,
                             double ms[][MAX_RUNS], int runs)
{
    char path[MAX_PATH];
    FILE *f;
    int i;
    if (snprintf(path, sizeof path, "%s/%s.csv", dir, scene) >= (int)sizeof path) return 0;
    f = fopen(path, "w");
    if (!f) return 0;
    fprintf(f, "threads,ms\n");
    for (i = 0; i < n; ++i) fprintf(f, "%d,%g\n", workers[i], sr_min(ms[i], runs));
    return fclose(f) == 0;
}

/* The directory part of path ("." when it has none), into dir. */
static void directory_of(const char *path, char *dir, size_t size)
{
    const char *slash = strrchr(path, '/');
    size_t n = slash ? (size_t)(slash - path) : 0;
    if (!slash) {
        snprintf(dir, size, ".");
        return;
    }
    if (n >= size) n = size - 1;
    memcpy(dir, path, n);
    dir[n] = 0;
}

/* BENCH_BOXES_ONLY: the box scenes only, in a build that works with a
   header from before shapes (ab_header.sh) */
static const char *const SCENES[] = {
    "large_pyramid", "many_pyramids", "smash", "tumbler", "pyramid20", "stack10",
#ifndef BENCH_BOXES_ONLY
    "rain",          "mixed_pile",    "mixed_bin",     "joint_grid",    "spinner",
#endif
};
#define SCENE_COUNT ((int)(sizeof SCENES / sizeof SCENES[0]))

/* Whether the command line asks for scene `name` (no names: every one). */
static int selected(int argc, char **argv, const char *name)
{
    int i;
    for (i = 2; i < argc; ++i)
        if (strcmp(argv[i], name) == 0) return 1;
    return argc <= 2;
}

/* The two scenes whose cost per constraint is compared */
#define JOINT_SCENE "joint_grid"
#define CONTACT_SCENE "large_pyramid"

/* What a scene's runs solved per timed step (the first run's: ga2d is
   deterministic, so every run solves the same), and its median ms/step. */
typedef struct solved {
    double contacts, joints, ms;
    int seen;
} solved;

/* µs of a whole step per constraint solved in it (NaN when none). */
static double us_per_constraint(const solved *v)
{
    double n = v->contacts + v->joints;
    return n > 0 ? 1e3 * v->ms / n : (double)NAN;
}

/* One table row and CSV line; returns 0 when every run went well. */
static int report(FILE *csv, const char *name, int bodies, double *ms, int runs, const char *figure_name, double figure,
                  int failed, int differ, double seconds, solved *v)
{
    double lo = sr_min(ms, runs), med = sr_median(ms, runs);
    v->ms = med;
    printf("%-14s %7d %12.4g %10.4g  %-26s %.3e%s%s\n", name, bodies, med, lo, figure_name, figure,
           differ ? "  (runs differ!)" : "", failed ? "  (FAILED)" : "");
    if (csv)
        fprintf(csv, "%s,%d,%.6g,%.6g,\"%s\",%.9g,%d,%d,%.2f,%.6g,%.6g,%.6g\n", name, bodies, med, lo, figure_name,
                figure, failed, differ, seconds, v->contacts, v->joints, us_per_constraint(v));
    return failed || differ;
}

/* The cost of a joint against a contact's, when both scenes ran. */
static void compare_costs(FILE *csv, const solved *joint, const solved *contact)
{
    double per_joint = us_per_constraint(joint), per_contact = us_per_constraint(contact);
    printf("cost per constraint (whole step / constraints solved per step; median ms/step):\n");
    printf("  %-14s %8.0f joints   %9.4g ms/step  %.4g us per joint\n", JOINT_SCENE, joint->joints, joint->ms,
           per_joint);
    printf("  %-14s %8.0f contacts %9.4g ms/step  %.4g us per contact\n", CONTACT_SCENE, contact->contacts, contact->ms,
           per_contact);
    printf("  per joint / per contact: %.3f (goal: at most 1)\n", per_joint / per_contact);
    if (csv)
        fprintf(csv, "%s/%s,%d,%.6g,%.6g,\"us per joint / us per contact\",%.9g,0,0,0,%.6g,%.6g,%.6g\n", JOINT_SCENE,
                CONTACT_SCENE, 0, per_joint, per_contact, per_joint / per_contact, contact->contacts, joint->joints,
                per_joint);
}

int main(int argc, char **argv)
{
    const int asked = sr_runs_from_env("BENCH_RUNS", DEFAULT_RUNS), runs = asked < MAX_RUNS ? asked : MAX_RUNS;
    FILE *csv = argc > 1 ? fopen(argv[1], "w") : NULL;
    double ms[MAX_RUNS], run_ms[WORKER_COUNT_N][MAX_RUNS], step_ms[WORKER_COUNT_N][MAX_RUNS], start = sr_now_ms();
    char csv_dir[MAX_PATH];
    solved joint = {0, 0, 0, 0}, contact = {0, 0, 0, 0};
    int i, r, c, bad = 0;
    if (argc > 1 && !csv) {
        fprintf(stderr, "bench_scenes: cannot write %s\n", argv[1]);
        return 1;
    }
    if (csv) directory_of(argv[1], csv_dir, sizeof csv_dir);
    printf("bench_scenes (ga2d_real %s): defaults, dt = 1/60; ms per ga2d_world_step over %d runs\n",
           sizeof(ga2d_real) == sizeof(double) ? "double" : "float", runs);
    printf("%-14s %7s %12s %10s  %-26s %s\n", "scene", "bodies", "ms/step med", "min", "figure", "value");
    if (csv)
        fprintf(csv, "scene,bodies,ms_per_step_median,ms_per_step_min,figure,value,failed,runs_differ,seconds,"
                     "contacts_per_step,joints_per_step,us_per_constraint\n");

    for (i = 0; i < SCENE_COUNT; ++i) {
        bench_scene s;
        ga2d_world_def wd;
        solved v = {0, 0, 0, 1};
        double figure = 0, gap = 0, t0 = sr_now_ms();
        int failed = 0, differ = 0;
        if (!selected(argc, argv, SCENES[i])) continue;
        if (bench_scene_make(SCENES[i], &s) != 0) {
            fprintf(stderr, "bench_scenes: cannot make %s\n", SCENES[i]);
            return 1;
        }
        /* a run of every worker count in each round, the order reversed
           every other round, so that a slow spell of the machine (its
           second core shared for a while: bench_cores) falls on each count
           alike; the table gives the first count's, and every count must
           give the first's figure bit for bit */
        for (r = 0; r < runs; ++r) {
            int turn;
            for (turn = 0; turn < WORKER_COUNT_N; ++turn) {
                sr_result res;
                c = r % 2 ? WORKER_COUNT_N - 1 - turn : turn;
                wd = sr_scene_def(&s, ga2d_default_world_def());
                if (!set_workers(&wd, WORKER_COUNTS[c])) {
                    fprintf(stderr, "bench_scenes: cannot step with %d workers\n", WORKER_COUNTS[c]);
                    return 1;
                }
                failed |= !sr_run_scene(&s, wd, 0, &res);
                if (c == 0) ms[r] = res.ms;
                step_ms[c][r] = res.ms;
                run_ms[c][r] = res.run_ms;
                if (c == 0 && r == 0) {
                    figure = res.figure;
                    gap = res.joint_gap;
                    v.contacts = res.contacts;
                    v.joints = res.joints;
                } else {
                    differ |= memcmp(&figure, &res.figure, sizeof figure) != 0;
                }
            }
        }
        bad |= report(csv, s.name, s.peak, ms, runs, bench_scene_figure_name(&s), figure, failed, differ,
                      (sr_now_ms() - t0) / 1e3, &v);
        if (csv && !failed && !write_threads_csv(csv_dir, s.name, WORKER_COUNTS, WORKER_COUNT_N, run_ms, runs)) {
            fprintf(stderr, "bench_scenes: cannot write %s/%s.csv\n", csv_dir, s.name);
            bad = 1;
        }
        for (c = 1; c < WORKER_COUNT_N && !failed; ++c) {
            double one[MAX_RUNS], more[MAX_RUNS], pair[MAX_RUNS];
            for (r = 0; r < runs; ++r) { /* the rounds' own ratios: runs of a round share the machine's spell */
                one[r] = step_ms[0][r];
                more[r] = step_ms[c][r];
                pair[r] = one[r] / more[r];
            }
            qsort(one, (size_t)runs, sizeof one[0], sr__cmp_double);
            qsort(more, (size_t)runs, sizeof more[0], sr__cmp_double);
            qsort(pair, (size_t)runs, sizeof pair[0], sr__cmp_double);
            printf("%-14s %7s %d workers: %.3f ms/step median, %.2f times one worker's speed (%.2f the median of the "
                   "rounds' ratios; the same bits: %s)\n",
                   "", "", WORKER_COUNTS[c], more[runs / 2], one[runs / 2] / more[runs / 2], pair[runs / 2],
                   differ ? "NO" : "yes");
        }
        if (s.joint_count > 0)
            printf("%-14s %7s %d joints, %.0f solved per step; worst joint separation at the end %.3e m\n", "", "",
                   s.joint_count, v.joints, gap);
        if (strcmp(s.name, JOINT_SCENE) == 0 && !failed) joint = v;
        if (strcmp(s.name, CONTACT_SCENE) == 0 && !failed) contact = v;
        bench_scene_free(&s);
    }

    for (i = 0; i < SR_CLOSED_FORM_COUNT; ++i) {
        double figure = 0, t0 = sr_now_ms();
        int failed = 0, differ = 0;
        if (!selected(argc, argv, sr_closed_form_name[i])) continue;
        for (r = 0; r < runs; ++r) {
            sr_result res;
            failed |= !sr_run_closed_form(i, ga2d_default_world_def(), &res);
            ms[r] = res.ms;
            if (r == 0)
                figure = res.figure;
            else
                differ |= memcmp(&figure, &res.figure, sizeof figure) != 0;
        }
        {
            solved none = {0, 0, 0, 0};
            bad |= report(csv, sr_closed_form_name[i], sr_closed_form_bodies[i], ms, runs, sr_closed_form_figure[i],
                          figure, failed, differ, (sr_now_ms() - t0) / 1e3, &none);
        }
    }
    if (joint.seen && contact.seen) compare_costs(csv, &joint, &contact);
    printf("bench_scenes: %.1f s in all\n", (sr_now_ms() - start) / 1e3);
    if (csv) fclose(csv);
    return bad;
}
