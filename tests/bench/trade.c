/* trade.c - what each knob of ga2d costs and what it buys, and what each
   optional pass costs when a scene does not need it (make trade).

   Built twice, as float and as double (-DGA2D_DOUBLE); three commands:

     trade knobs OUT.csv N  round N of the knob sweep, appended to OUT.csv:
                            every configuration run once, in this build's
                            precision, over the scenes where they matter:
                              pyramid20, stack10 (top box drift): substeps
                                1/2/4/8 x solver kind, warm starting off,
                                sleep on, Verlet, RK4, the linear rotor
                                update, the accurate setting;
                              oscillator (max error): integrator x substeps;
                              spin (angle error): rotor update x substeps;
                              bounce (worst apex error): integrator x
                                substeps, restitution off.
     trade passes OUT.csv   each optional pass on versus off: friction,
                            restitution, rotation (every box fixed_rotation
                            when off), sleep, warm starting on pyramid20;
                            and the broadphase of worlds of 2 to 10 bodies.
     trade report DIR KNOBS.csv... PASSES.csv
                            reads the CSVs, writes DIR/<scene>.svg (error
                            against ms per step, every configuration a
                            labelled point, float and double together, the
                            Pareto front marked) and DIR/tables.md, and
                            prints the tables.

   Times are ms per ga2d_world_step, measured as scene_run.h says: for the
   knobs the median over the rounds (make trade runs TRADE_RUNS rounds,
   default 5, float and double in turn), for the passes over TRADE_RUNS
   runs (default 5) with on and off alternating.  Interleaving puts a slow
   spell of this shared machine on every configuration alike.  Each
   configuration's figure must come out bit for bit the same in every run
   (ga2d is deterministic); a run that differs or fails is flagged in the
   tables.  Run from the repository root. */
#define _POSIX_C_SOURCE 199309L
#define GA2D_IMPLEMENTATION
#include "ga2d_physics.h"
#include "scenes.h"
#include "scene_run.h"
#include "svg_plot.h"
#include <stdarg.h>

#define MAX_RUNS 64
#define MAX_CONFIGS 40
#define MAX_ROWS 512
#define LABEL 40

static const char *const SOLVER_NAME[] = {"soft", "PGS-B", "NGS"};
static const char *const SOLVER_LONG[] = {"soft step", "PGS + Baumgarte", "PGS + NGS"};
static const char *const INTEGRATOR_NAME[] = {"SE", "Verlet", "RK4"};
static const char *const INTEGRATOR_LONG[] = {"symplectic Euler", "Verlet", "RK4"};
static const char *const ROTATION_NAME[] = {"exact", "linear"};

/* ------------------------------------------------------------ knobs */
/* One setting of every knob.  accurate: the world def is
   ga2d_accurate_world_def() (8 substeps, 90 Hz); substeps and solver then
   stay at the defaults' values here, so it differs from the defaults in
   that one knob. */
typedef struct config {
    int substeps, solver, integrator, rotation;
    int warm, sleep, restitution, accurate;
} config;

/* Which knobs a scene sweeps. */
enum { FAMILY_SOLVER, FAMILY_INTEGRATOR, FAMILY_ROTATION, FAMILY_BOUNCE };

typedef struct trade_scene {
    const char *name;
    int family;
    int closed_form; /* SR_* for a closed-form scene, -1 for scenes.h's */
    int sleep;       /* the scene's own sleep switch (its default) */
} trade_scene;

static const trade_scene SCENES[] = {
    {"pyramid20", FAMILY_SOLVER, -1, 0},
    {"stack10", FAMILY_SOLVER, -1, 0},
    {"oscillator", FAMILY_INTEGRATOR, SR_OSCILLATOR, 1},
    {"spin", FAMILY_ROTATION, SR_SPIN, 1},
    {"bounce", FAMILY_BOUNCE, SR_BOUNCE, 1},
};
#define SCENE_COUNT ((int)(sizeof SCENES / sizeof SCENES[0]))

static config defaults_of(const trade_scene *sc)
{
    config c;
    c.substeps = 4;
    c.solver = GA2D_SOLVER_SOFT_STEP;
    c.integrator = GA2D_INTEGRATOR_SYMPLECTIC_EULER;
    c.rotation = GA2D_ROTATION_EXACT;
    c.warm = 1;
    c.sleep = sc->sleep;
    c.restitution = 1;
    c.accurate = 0;
    return c;
}

/* The configurations swept for scene sc; returns how many. */
static int configs_of(const trade_scene *sc, config *out)
{
    static const int substeps[4] = {1, 2, 4, 8};
    const config d = defaults_of(sc);
    int n = 0, i, k;
    if (sc->family == FAMILY_SOLVER) {
        for (k = 0; k < GA2D_SOLVER_COUNT; ++k)
            for (i = 0; i < 4; ++i) {
                out[n] = d;
                out[n].solver = k;
                out[n++].substeps = substeps[i];
            }
        for (k = 0; k < GA2D_SOLVER_COUNT; ++k) {
            out[n] = d;
            out[n].solver = k;
            out[n++].warm = 0;
            out[n] = d;
            out[n].solver = k;
            out[n++].sleep = 1;
        }
        out[n] = d;
        out[n++].integrator = GA2D_INTEGRATOR_VERLET;
        out[n] = d;
        out[n++].integrator = GA2D_INTEGRATOR_RK4;
        out[n] = d;
        out[n++].rotation = GA2D_ROTATION_LINEAR;
        out[n] = d;
        out[n++].accurate = 1;
    } else {
        int kinds = sc->family == FAMILY_ROTATION ? GA2D_ROTATION_COUNT : GA2D_INTEGRATOR_COUNT;
        for (k = 0; k < kinds; ++k)
            for (i = 0; i < 4; ++i) {
                out[n] = d;
                if (sc->family == FAMILY_ROTATION)
                    out[n].rotation = k;
                else
                    out[n].integrator = k;
                out[n++].substeps = substeps[i];
            }
        if (sc->family == FAMILY_BOUNCE) {
            out[n] = d;
            out[n++].restitution = 0;
        }
    }
    return n;
}

static ga2d_world_def def_of(const config *c)
{
    ga2d_world_def wd = c->accurate ? ga2d_accurate_world_def() : ga2d_default_world_def();
    if (!c->accurate) {
        wd.substeps = c->substeps;
        wd.solver = (ga2d_solver)c->solver;
    }
    wd.integrator = (ga2d_integrator)c->integrator;
    wd.rotation_update = (ga2d_rotation_update)c->rotation;
    wd.enable_warm_starting = c->warm;
    wd.enable_sleep = c->sleep;
    wd.enable_restitution = c->restitution;
    return wd;
}

/* A short name for the plot and the tables: the knobs the scene's family
   sweeps, then whatever else differs from the defaults. */
static void label_of(const trade_scene *sc, const config *c, char *out, size_t size)
{
    const config d = defaults_of(sc);
    if (c->accurate) {
        snprintf(out, size, "accurate");
        return;
    }
    if (sc->family == FAMILY_SOLVER)
        snprintf(out, size, "%s %d%s%s%s%s%s", SOLVER_NAME[c->solver], c->substeps, c->warm ? "" : " no-warm",
                 c->sleep != d.sleep ? " sleep" : "", c->integrator != d.integrator ? " " : "",
                 c->integrator != d.integrator ? INTEGRATOR_NAME[c->integrator] : "",
                 c->rotation != d.rotation ? " lin-rot" : "");
    else if (sc->family == FAMILY_ROTATION)
        snprintf(out, size, "%s %d", ROTATION_NAME[c->rotation], c->substeps);
    else if (!c->restitution)
        snprintf(out, size, "no restitution");
    else
        snprintf(out, size, "%s %d", INTEGRATOR_NAME[c->integrator], c->substeps);
}

/* One run of scene sc under c. */
static int run_config(const trade_scene *sc, const bench_scene *bs, const config *c, sr_result *r)
{
    ga2d_world_def wd = def_of(c);
    if (sc->closed_form >= 0) return sr_run_closed_form(sc->closed_form, wd, r);
    wd.gravity = ga2d_vec_make((ga2d_real)bs->gx, (ga2d_real)bs->gy);
    return sr_run_scene(bs, wd, 0, r);
}

static const char *precision(void) { return sizeof(ga2d_real) == sizeof(double) ? "double" : "float"; }

/* TRADE_RUNS, or the fallback; at most MAX_RUNS. */
static int run_count(int fallback)
{
    int n = sr_runs_from_env("TRADE_RUNS", fallback);
    return n < MAX_RUNS ? n : MAX_RUNS;
}

/* One round: every configuration of every scene run once, appended to
   the CSV at path (its header first when the file is new).  make trade
   calls it round after round, float and double in turn, so a slow spell
   of the machine falls on both precisions and all configurations alike;
   the report takes the medians. */
static int knobs(const char *path, int round)
{
    FILE *csv = fopen(path, "a");
    int s, bad = 0;
    double t0 = sr_now_ms();
    if (!csv) {
        fprintf(stderr, "trade: cannot write %s\n", path);
        return 1;
    }
    if (ftell(csv) == 0)
        fprintf(csv, "scene,precision,label,substeps,solver,integrator,rotation,warm,sleep,restitution,accurate,"
                     "is_default,round,ms,error,failed\n");
    for (s = 0; s < SCENE_COUNT; ++s) {
        const trade_scene *sc = &SCENES[s];
        const config d = defaults_of(sc);
        config cfg[MAX_CONFIGS];
        int n = configs_of(sc, cfg), i;
        bench_scene bs;
        memset(&bs, 0, sizeof bs);
        if (sc->closed_form < 0 && bench_scene_make(sc->name, &bs) != 0) {
            fprintf(stderr, "trade: cannot make %s\n", sc->name);
            fclose(csv);
            return 1;
        }
        for (i = 0; i < n; ++i) {
            char label[LABEL];
            const config *c = &cfg[i];
            sr_result res;
            int ok = run_config(sc, &bs, c, &res);
            label_of(sc, c, label, sizeof label);
            /* %.17g: the figure round-trips, so the report can check that
               every round gave the same bits */
            fprintf(csv, "%s,%s,%s,%d,%d,%d,%d,%d,%d,%d,%d,%d,%d,%.6g,%.17g,%d\n", sc->name, precision(), label,
                    c->substeps, c->solver, c->integrator, c->rotation, c->warm, c->sleep, c->restitution, c->accurate,
                    memcmp(c, &d, sizeof d) == 0, round, res.ms, res.figure, !ok);
            bad |= !ok;
        }
        if (sc->closed_form < 0) bench_scene_free(&bs);
    }
    printf("trade knobs (%s): round %d, %.1f s\n", precision(), round, (sr_now_ms() - t0) / 1e3);
    fclose(csv);
    return bad;
}

/* ------------------------------------------------------------ passes */
/* A world of n bodies for the broadphase rows: a static ground and a
   stack of n - 1 boxes at rest, or n boxes falling freely side by side
   (no ground), each leaving its fat box most steps; ids[] gets every
   body (n <= TINY_MAX). */
#define TINY_MAX 16
static ga2d_world *tiny_world(int n, int falling, ga2d_body_id *ids)
{
    ga2d_world_def wd = ga2d_default_world_def();
    ga2d_body_def d = ga2d_default_body_def();
    ga2d_world *w;
    int i;
    wd.enable_sleep = 0;
    w = ga2d_world_create(&wd);
    if (!w) return NULL;
    for (i = 0; i < n; ++i) {
        if (i == 0 && !falling) {
            d.polygon = ga2d_polygon_box(100, 1);
            d.position = ga2d_vec_make(0, -1);
        } else {
            d.type = GA2D_BODY_DYNAMIC;
            d.polygon = ga2d_polygon_box((ga2d_real)0.5, (ga2d_real)0.5);
            d.position = falling ? ga2d_vec_make((ga2d_real)(2 * i), 0) : ga2d_vec_make(0, (ga2d_real)(i - 0.5));
        }
        ids[i] = ga2d_body_create(w, &d);
        if (ga2d_body_id_is_null(ids[i])) {
            ga2d_world_destroy(w);
            return NULL;
        }
    }
    return w;
}

#define TINY_STEPS 600
#define BRUTE_REPEATS 20000
static volatile int sink; /* the all-pairs test's answers go somewhere */

/* What the broadphase costs in a tiny world, measured on the library's
   own pass (ga2d has no switch for it): each step first runs
   its broadphase stages (broadphase_stages), timed on their own;
   the step that follows then finds nothing queued and gives the same
   bits as it would have.  The clock's own cost, timed the same way around
   nothing, is taken off.  The alternative a tiny world could use instead,
   testing every pair's fat boxes, is timed over the same boxes.
   Returns ms per step of the plain step (stepped alone, in another world),
   and *bp and *brute in ms per step. */
/* The broadphase stages of a step (ga2d__step's first five), run on their
   own with the last step's dt. */
static void broadphase_stages(ga2d_world *w)
{
    ga2d__step_context *c = &w->step;
    ga2d__bits_zero(c->refits, w->moving_count);
    ga2d__run(c, ga2d__mark_refits, w->moving_count);
    ga2d__refit_proxies(c);
    ga2d__run(c, ga2d__find_pairs, w->move_count);
    ga2d__create_pairs(c);
}

static double tiny_run(int n, int falling, double *bp, double *brute)
{
    ga2d_body_id ids[TINY_MAX];
    ga2d_world *w = tiny_world(n, falling, ids);
    ga2d_aabb box[TINY_MAX];
    const volatile ga2d_aabb *vbox = box;
    double t0, plain = 0, pairs = 0, clock_cost = 0;
    int k, i, j, hits = 0, rep;
    if (!w) return (double)NAN;
    for (k = 0; k < TINY_STEPS; ++k) {
        t0 = sr_now_ms();
        ga2d_world_step(w, (ga2d_real)(1.0 / 60));
        if (k >= SR_WARMUP) plain += sr_now_ms() - t0;
    }
    ga2d_world_destroy(w);
    w = tiny_world(n, falling, ids);
    if (!w) return (double)NAN;
    for (k = 0; k < TINY_STEPS; ++k) {
        double t1;
        t0 = sr_now_ms();
        broadphase_stages(w);
        t1 = sr_now_ms();
        if (k >= SR_WARMUP) pairs += t1 - t0;
        t0 = sr_now_ms();
        t1 = sr_now_ms();
        if (k >= SR_WARMUP) clock_cost += t1 - t0;
        ga2d_world_step(w, (ga2d_real)(1.0 / 60));
    }
    /* every pair's fat boxes (this last state's), many times over; read
       through a volatile pointer so the compiler cannot test once and
       reuse the answers */
    for (i = 0; i < n; ++i) box[i] = ga2d_body_fat_aabb(w, ids[i]);
    t0 = sr_now_ms();
    for (rep = 0; rep < BRUTE_REPEATS; ++rep)
        for (i = 0; i < n; ++i)
            for (j = i + 1; j < n; ++j) hits += ga2d_aabb_overlaps(vbox[i], vbox[j]);
    *brute = (sr_now_ms() - t0) / BRUTE_REPEATS;
    sink = hits;
    *bp = (pairs - clock_cost) / (TINY_STEPS - SR_WARMUP);
    if (*bp < 0) *bp = 0;
    ga2d_world_destroy(w);
    return plain / (TINY_STEPS - SR_WARMUP);
}

/* The passes of pyramid20: setting k on (1) or off (0). */
enum { PASS_FRICTION, PASS_RESTITUTION, PASS_ROTATION, PASS_SLEEP, PASS_WARM, PASS_COUNT };
static const char *const PASS_NAME[PASS_COUNT] = {"friction", "restitution", "rotation", "sleep", "warm starting"};
static const char *const PASS_NOTE[PASS_COUNT] = {
    "boxes slide apart without it", "every box has e = 0: nothing to bounce", "off: every box fixed_rotation",
    "the pyramid settles and sleeps", "off: impulses start from 0 each step"};

static int pass_run(const bench_scene *bs, int pass, int on, sr_result *r)
{
    ga2d_world_def wd = sr_scene_def(bs, ga2d_default_world_def());
    int fixed = 0;
    if (pass == PASS_FRICTION) wd.enable_friction = on;
    if (pass == PASS_RESTITUTION) wd.enable_restitution = on;
    if (pass == PASS_ROTATION) fixed = !on;
    if (pass == PASS_SLEEP) wd.enable_sleep = on;
    if (pass == PASS_WARM) wd.enable_warm_starting = on;
    return sr_run_scene(bs, wd, fixed, r);
}

static int passes(const char *path)
{
    const int runs = run_count(5);
    static const int tiny_n[4] = {2, 5, 10, 10}, tiny_falling[4] = {0, 0, 0, 1};
    FILE *csv = fopen(path, "w");
    bench_scene bs;
    int p, r, k, bad = 0;
    if (!csv || bench_scene_make("pyramid20", &bs) != 0) {
        fprintf(stderr, "trade: cannot write %s or make pyramid20\n", path);
        if (csv) fclose(csv);
        return 1;
    }
    fprintf(csv, "pass,scene,bodies,ms_on,ms_off,on_over_off,figure,figure_on,figure_off,estimate,note,failed\n");
    for (p = 0; p < PASS_COUNT; ++p) {
        double ms[2][MAX_RUNS], fig[2] = {0, 0};
        int failed = 0, differ = 0, on;
        for (r = 0; r < runs; ++r)
            for (on = 1; on >= 0; --on) {
                sr_result res;
                failed |= !pass_run(&bs, p, on, &res);
                ms[on][r] = res.ms;
                if (r == 0)
                    fig[on] = res.figure;
                else
                    differ |= memcmp(&fig[on], &res.figure, sizeof fig[on]) != 0;
            }
        {
            double m_on = sr_median(ms[1], runs), m_off = sr_median(ms[0], runs);
            fprintf(csv, "%s,pyramid20,%d,%.6g,%.6g,%.4f,top box drift (m),%.6g,%.6g,0,%s,%d\n", PASS_NAME[p], bs.count,
                    m_on, m_off, m_on / m_off, fig[1], fig[0], PASS_NOTE[p], failed || differ);
        }
        bad |= failed || differ;
        printf("trade passes: %s\n", PASS_NAME[p]);
        fflush(stdout);
    }
    bench_scene_free(&bs);
    for (k = 0; k < 4; ++k) {
        double plain[MAX_RUNS], bp[MAX_RUNS], brute[MAX_RUNS], m_on, m_bp, m_brute;
        for (r = 0; r < runs; ++r) plain[r] = tiny_run(tiny_n[k], tiny_falling[k], &bp[r], &brute[r]);
        m_on = sr_median(plain, runs);
        m_bp = sr_median(bp, runs);
        m_brute = sr_median(brute, runs);
        /* without a tree: the step less its broadphase, plus the all-pairs test */
        fprintf(csv, "broadphase (tree),%s %d,%d,%.6g,%.6g,%.4f,broadphase ms/step,%.6g,%.6g,1,%s,%d\n",
                tiny_falling[k] ? "falling" : "stack", tiny_n[k], tiny_n[k], m_on, m_on - m_bp + m_brute,
                m_on / (m_on - m_bp + m_brute), m_bp, m_brute,
                "no switch: off = step - its broadphase + an all-pairs box test", !isfinite(m_on));
        bad |= !isfinite(m_on);
    }
    printf("trade passes: broadphase\n");
    fclose(csv);
    return bad;
}

/* ------------------------------------------------------------ report */
/* One configuration of one scene in one precision, over its rounds. */
typedef struct row {
    char scene[24], precision[8], label[LABEL];
    config c;
    int is_default, failed, differ, runs;
    double ms, ms_min, error;
    double round_ms[MAX_RUNS];
} row;

/* Splits line at commas into at most n fields (no quoting: our CSVs have
   none); returns the count. */
static int split(char *line, char **field, int n)
{
    int k = 0;
    char *s = line;
    line[strcspn(line, "\r\n")] = 0;
    while (k < n) {
        field[k++] = s;
        s = strchr(s, ',');
        if (!s) break;
        *s++ = 0;
    }
    return k;
}

/* Adds the rounds in the knobs CSV at path to rows[0..n-1] (a new row
   per configuration first seen); returns the new count, or -1. */
static int read_knobs(const char *path, row *rows, int n)
{
    FILE *f = fopen(path, "r");
    char line[512], *fld[16];
    int i;
    if (!f) {
        fprintf(stderr, "trade: cannot read %s\n", path);
        return -1;
    }
    if (!fgets(line, sizeof line, f)) line[0] = 0; /* the header */
    while (fgets(line, sizeof line, f)) {
        row *r;
        double error;
        if (split(line, fld, 16) != 16) continue;
        for (i = 0; i < n; ++i)
            if (strcmp(rows[i].scene, fld[0]) == 0 && strcmp(rows[i].precision, fld[1]) == 0 &&
                strcmp(rows[i].label, fld[2]) == 0)
                break;
        if (i == n) {
            if (n == MAX_ROWS) continue;
            r = &rows[n++];
            memset(r, 0, sizeof *r);
            snprintf(r->scene, sizeof r->scene, "%s", fld[0]);
            snprintf(r->precision, sizeof r->precision, "%s", fld[1]);
            snprintf(r->label, sizeof r->label, "%s", fld[2]);
            r->c.substeps = atoi(fld[3]);
            r->c.solver = atoi(fld[4]);
            r->c.integrator = atoi(fld[5]);
            r->c.rotation = atoi(fld[6]);
            r->c.warm = atoi(fld[7]);
            r->c.sleep = atoi(fld[8]);
            r->c.restitution = atoi(fld[9]);
            r->c.accurate = atoi(fld[10]);
            r->is_default = atoi(fld[11]);
            r->error = strtod(fld[14], NULL);
        }
        r = &rows[i];
        error = strtod(fld[14], NULL);
        r->differ |= memcmp(&error, &r->error, sizeof error) != 0;
        r->failed |= atoi(fld[15]);
        if (r->runs < MAX_RUNS) r->round_ms[r->runs++] = strtod(fld[13], NULL);
    }
    fclose(f);
    for (i = 0; i < n; ++i) {
        double sorted[MAX_RUNS];
        memcpy(sorted, rows[i].round_ms, sizeof sorted);
        rows[i].ms_min = sr_min(sorted, rows[i].runs);
        rows[i].ms = sr_median(sorted, rows[i].runs);
    }
    return n;
}

/* The figure's name: scenes.h's for its scenes (the solver scenes here
   are all measured by drift). */
static const char *figure_of(const trade_scene *sc)
{
    bench_scene drift;
    memset(&drift, 0, sizeof drift);
    drift.figure = BENCH_FIG_DRIFT;
    return sc->closed_form >= 0 ? sr_closed_form_figure[sc->closed_form] : bench_scene_figure_name(&drift);
}

/* The one knob in which a differs from b, or NULL if none or several. */
static const char *knob_changed(const config *a, const config *b)
{
    const char *name = NULL;
    int n = 0;
    if (a->substeps != b->substeps) name = "substeps", ++n;
    if (a->solver != b->solver) name = "solver kind", ++n;
    if (a->integrator != b->integrator) name = "integrator", ++n;
    if (a->rotation != b->rotation) name = "rotor update", ++n;
    if (a->warm != b->warm) name = "warm starting", ++n;
    if (a->sleep != b->sleep) name = "sleep", ++n;
    if (a->restitution != b->restitution) name = "restitution", ++n;
    if (a->accurate != b->accurate) name = "accurate setting", ++n;
    return n == 1 ? name : NULL;
}

static void setting_of(const char *knob, const config *c, char *out, size_t size)
{
    if (strcmp(knob, "substeps") == 0)
        snprintf(out, size, "%d substeps", c->substeps);
    else if (strcmp(knob, "solver kind") == 0)
        snprintf(out, size, "%s", SOLVER_LONG[c->solver]);
    else if (strcmp(knob, "integrator") == 0)
        snprintf(out, size, "%s", INTEGRATOR_LONG[c->integrator]);
    else if (strcmp(knob, "rotor update") == 0)
        snprintf(out, size, "%s", ROTATION_NAME[c->rotation]);
    else if (strcmp(knob, "warm starting") == 0)
        snprintf(out, size, "%s", c->warm ? "on" : "off");
    else if (strcmp(knob, "sleep") == 0)
        snprintf(out, size, "%s", c->sleep ? "on" : "off");
    else if (strcmp(knob, "restitution") == 0)
        snprintf(out, size, "%s", c->restitution ? "on" : "off");
    else
        snprintf(out, size, "8 substeps, 90 Hz");
}

/* What a change does, in words, from its cost and error ratios: within 5 %
   of the cost and 10 % of the error counts as the same. */
static const char *verdict(double cost, double error)
{
    int cheaper = cost<0.95, dearer = cost> 1.05;
    int better = error<0.9, worse = error> 1.1;
    if (better && !dearer) return cheaper ? "better and cheaper" : "better, same cost";
    if (better) return "better, costs more";
    if (worse && !cheaper) return dearer ? "worse and dearer" : "worse, same cost";
    if (worse) return "worse, saves time";
    if (cheaper) return "same error, cheaper";
    return dearer ? "same error, dearer" : "no change";
}

/* Printed, and written to md. */
static void out2(FILE *md, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vprintf(fmt, ap);
    va_end(ap);
    va_start(ap, fmt);
    vfprintf(md, fmt, ap);
    va_end(ap);
}

static void plot_scene(const char *dir, const trade_scene *sc, const row *rows, int n)
{
    static const char *const rot_series[2] = {"exact rotor update", "linear rotor update"};
    svgp_plot plot;
    char path[512], title[128], subtitle[200];
    int i, runs = 0;
    for (i = 0; i < n; ++i)
        if (strcmp(rows[i].scene, sc->name) == 0 && rows[i].runs > runs) runs = rows[i].runs;
    snprintf(title, sizeof title, "%s: %s against cost", sc->name, figure_of(sc));
    snprintf(subtitle, sizeof subtitle,
             "each point one configuration; cost: median ms per ga2d_world_step of %d runs, on the machine "
             "that ran make trade",
             runs);
    svgp_init(&plot, title, subtitle, "ms per step", figure_of(sc));
    if (sc->family == FAMILY_SOLVER) {
        for (i = 0; i < GA2D_SOLVER_COUNT; ++i) svgp_series(&plot, i, SOLVER_LONG[i]);
        svgp_series(&plot, 3, "accurate setting");
    } else if (sc->family == FAMILY_ROTATION) {
        for (i = 0; i < 2; ++i) svgp_series(&plot, i, rot_series[i]);
    } else {
        for (i = 0; i < GA2D_INTEGRATOR_COUNT; ++i) svgp_series(&plot, i, INTEGRATOR_LONG[i]);
        if (sc->family == FAMILY_BOUNCE) svgp_series(&plot, 3, "restitution off");
    }
    svgp_marker(&plot, 0, "float");
    svgp_marker(&plot, 1, "double");
    for (i = 0; i < n; ++i) {
        const row *r = &rows[i];
        int series, dbl = strcmp(r->precision, "double") == 0;
        char label[LABEL + 8];
        if (strcmp(r->scene, sc->name) != 0 || r->failed) continue;
        if (sc->family == FAMILY_SOLVER)
            series = r->c.accurate ? 3 : r->c.solver;
        else if (sc->family == FAMILY_ROTATION)
            series = r->c.rotation;
        else
            series = r->c.restitution ? r->c.integrator : 3;
        snprintf(label, sizeof label, "%s%s", r->label, dbl ? " (d)" : "");
        svgp_add(&plot, r->ms, r->error, label, series, dbl);
    }
    snprintf(path, sizeof path, "%s/%s.svg", dir, sc->name);
    if (svgp_write(&plot, path) != 0) fprintf(stderr, "trade: cannot write %s\n", path);
}

/* The scene's default rows, float and double (NULL where missing). */
static void default_rows(const row *rows, int n, const char *scene, const row **f, const row **d)
{
    int i;
    *f = *d = NULL;
    for (i = 0; i < n; ++i)
        if (strcmp(rows[i].scene, scene) == 0 && rows[i].is_default) {
            if (strcmp(rows[i].precision, "float") == 0)
                *f = &rows[i];
            else
                *d = &rows[i];
        }
}

static int report(const char *dir, char **knob_csv, int knob_count, const char *passes_csv)
{
    static row rows[MAX_ROWS];
    char path[512], line[512], *fld[12];
    FILE *md, *pf;
    int n = 0, i, j, s, k, bad = 0;
    static const char *const knob_order[] = {"substeps",      "solver kind", "integrator",  "rotor update",
                                             "warm starting", "sleep",       "restitution", "accurate setting"};
    for (i = 0; i < knob_count; ++i) {
        n = read_knobs(knob_csv[i], rows, n);
        if (n < 0) return 1;
    }
    snprintf(path, sizeof path, "%s/tables.md", dir);
    md = fopen(path, "w");
    if (!md) {
        fprintf(stderr, "trade: cannot write %s\n", path);
        return 1;
    }
    for (i = 0; i < n; ++i) bad |= rows[i].failed || rows[i].differ;

    out2(md, "# ga2d: what each knob costs and buys (make trade)\n\n");
    out2(md, "Generated by `make trade` (tests/bench/trade.c). ms/step is the median time of one\n"
             "`ga2d_world_step` over the runs, on the machine that ran it; compare rows with each\n"
             "other. Ratios (x) are against the scene's defaults (4 substeps, soft step, symplectic\n"
             "Euler, exact rotor update, warm starting on) in the same build, except the double\n"
             "rows, which compare the double build's defaults with the float build's (the two\n"
             "builds ran their rounds in turn). Sleep is off in pyramid20 and stack10 (as in\n"
             "scenes.h) and on in the one-body scenes (the default world's setting).\n\n");

    out2(md, "## Defaults\n\n| scene | figure | float ms/step | float error | double ms/step | double error |\n"
             "|---|---|---|---|---|---|\n");
    for (s = 0; s < SCENE_COUNT; ++s) {
        const row *f, *d;
        default_rows(rows, n, SCENES[s].name, &f, &d);
        if (!f) continue;
        out2(md, "| %s | %s | %.4g | %.3g |", SCENES[s].name, figure_of(&SCENES[s]), f->ms, f->error);
        if (d)
            out2(md, " %.4g | %.3g |\n", d->ms, d->error);
        else
            out2(md, " - | - |\n");
    }

    out2(md, "\n## Knobs, one changed from the defaults (float unless said)\n\n");
    out2(md, "| knob | setting | scene | ms/step | cost x | error | error x | trade |\n"
             "|---|---|---|---|---|---|---|---|\n");
    for (k = 0; k < (int)(sizeof knob_order / sizeof knob_order[0]); ++k)
        for (s = 0; s < SCENE_COUNT; ++s) {
            const row *d = NULL;
            for (i = 0; i < n; ++i)
                if (rows[i].is_default && strcmp(rows[i].scene, SCENES[s].name) == 0 &&
                    strcmp(rows[i].precision, "float") == 0)
                    d = &rows[i];
            if (!d) continue;
            for (i = 0; i < n; ++i) {
                const row *r = &rows[i];
                const char *knob;
                char setting[64];
                if (strcmp(r->scene, d->scene) != 0 || strcmp(r->precision, "float") != 0) continue;
                knob = knob_changed(&r->c, &d->c);
                if (!knob || strcmp(knob, knob_order[k]) != 0) continue;
                setting_of(knob, &r->c, setting, sizeof setting);
                out2(md, "| %s | %s | %s | %.4g | %.2f | %.3g | %.3g | %s%s |\n", knob, setting, r->scene, r->ms,
                     r->ms / d->ms, r->error, d->error > 0 ? r->error / d->error : (double)NAN,
                     verdict(r->ms / d->ms, d->error > 0 ? r->error / d->error : 1),
                     r->failed || r->differ ? " (FAILED or runs differ)" : "");
            }
        }
    for (s = 0; s < SCENE_COUNT; ++s) {
        const row *f, *d;
        default_rows(rows, n, SCENES[s].name, &f, &d);
        if (f && d)
            out2(md, "| precision | double | %s | %.4g | %.2f | %.3g | %.3g | %s |\n", d->scene, d->ms, d->ms / f->ms,
                 d->error, f->error > 0 ? d->error / f->error : (double)NAN,
                 verdict(d->ms / f->ms, f->error > 0 ? d->error / f->error : 1));
    }

    out2(md, "\n## Pareto front per scene (float and double; nothing else is both cheaper and better)\n\n");
    out2(md, "| scene | configuration | precision | ms/step | error |\n|---|---|---|---|---|\n");
    for (s = 0; s < SCENE_COUNT; ++s) {
        const row *front[MAX_ROWS];
        int nf = 0;
        for (i = 0; i < n; ++i) {
            const row *a = &rows[i];
            int dominated = 0;
            if (strcmp(a->scene, SCENES[s].name) != 0 || a->failed) continue;
            for (j = 0; j < n && !dominated; ++j) {
                const row *b = &rows[j];
                dominated = j != i && !b->failed && strcmp(b->scene, a->scene) == 0 && b->ms <= a->ms &&
                            b->error <= a->error && (b->ms < a->ms || b->error < a->error);
            }
            if (!dominated) front[nf++] = a;
        }
        for (i = 1; i < nf; ++i) /* by cost */
            for (j = i; j > 0 && front[j - 1]->ms > front[j]->ms; --j) {
                const row *t = front[j];
                front[j] = front[j - 1];
                front[j - 1] = t;
            }
        for (i = 0; i < nf; ++i)
            out2(md, "| %s | %s | %s | %.4g | %.3g |\n", front[i]->scene, front[i]->label, front[i]->precision,
                 front[i]->ms, front[i]->error);
    }

    pf = fopen(passes_csv, "r");
    if (!pf) {
        fprintf(stderr, "trade: cannot read %s\n", passes_csv);
        fclose(md);
        return 1;
    }
    out2(md, "\n## Optional passes: what each costs when on versus off\n\n");
    out2(md, "Model only what a scene requires: each pass timed on and off in alternating runs\n"
             "of one process (float). The figure says what the pass buys in that scene.\n\n");
    out2(md, "| pass | scene | bodies | ms/step on | ms/step off | on/off | figure | on | off | note |\n"
             "|---|---|---|---|---|---|---|---|---|---|\n");
    if (!fgets(line, sizeof line, pf)) line[0] = 0;
    while (fgets(line, sizeof line, pf)) {
        if (split(line, fld, 12) != 12) continue;
        out2(md, "| %s | %s | %s | %.4g | %.4g%s | %.3f | %s | %.3g | %.3g | %s%s |\n", fld[0], fld[1], fld[2],
             strtod(fld[3], NULL), strtod(fld[4], NULL), atoi(fld[9]) ? " (est.)" : "", strtod(fld[5], NULL), fld[6],
             strtod(fld[7], NULL), strtod(fld[8], NULL), fld[10], atoi(fld[11]) ? " (FAILED or runs differ)" : "");
        bad |= atoi(fld[11]);
    }
    fclose(pf);
    out2(md, "\nbroadphase (tree): ga2d has no switch to turn it off. Its cost is measured on the\n"
             "library's own broadphase pass, run and timed alone before each step; \"off\" is the\n"
             "step without it plus a test of every pair's fat boxes (the all-pairs alternative);\n"
             "the figure columns are those two costs in ms/step.\n");
    fclose(md);

    for (s = 0; s < SCENE_COUNT; ++s) plot_scene(dir, &SCENES[s], rows, n);
    printf("\ntrade: wrote %s and %d plots in %s\n", path, SCENE_COUNT, dir);
    return bad;
}

int main(int argc, char **argv)
{
    if (argc == 4 && strcmp(argv[1], "knobs") == 0) return knobs(argv[2], atoi(argv[3]));
    if (argc == 3 && strcmp(argv[1], "passes") == 0) return passes(argv[2]);
    if (argc >= 5 && strcmp(argv[1], "report") == 0) return report(argv[2], argv + 3, argc - 4, argv[argc - 1]);
    fprintf(stderr, "usage: trade knobs OUT.csv ROUND | trade passes OUT.csv | trade report DIR KNOBS.csv... "
                    "PASSES.csv\n");
    return 2;
}
