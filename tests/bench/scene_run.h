/* scene_run.h - runs scenes in ga2d for the benchmarks (bench_scenes.c,
   trade.c): the engine-neutral scenes of scenes.h, and four one-body
   scenes whose exact motion is known in closed form.

   Include it after ga2d_physics.h (with GA2D_IMPLEMENTATION) and scenes.h,
   in a file that defines _POSIX_C_SOURCE >= 199309L before any include
   (clock_gettime).

   Timing: only ga2d_world_step is timed, and the first SR_WARMUP steps of a
   run are left out (the first steps build every pair and contact at once).
   A scenes.h scene times each step on its own, since the driver has work
   between steps (turning the tumbler, reading contacts, making and
   destroying the bodies of rain and mixed_pile) that must not be
   counted; a step there costs far more than the clock.  The closed-form
   scenes step one body, where a step can cost less than reading the clock
   twice, so they are timed as whole loops with nothing else in them, over
   fresh worlds until SR_MIN_TIMED_MS of stepping is collected, and their
   figure comes from a separate run that reads the state after every step. */
#ifndef GA2D_BENCH_SCENE_RUN_H
#define GA2D_BENCH_SCENE_RUN_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#if defined(__GNUC__) || defined(__clang__)
#define SR_FN static __attribute__((unused))
#else
#define SR_FN static
#endif

#define SR_WARMUP 10
#define SR_MIN_TIMED_MS 20.0
#define SR_PI 3.14159265358979323846

/* ------------------------------------------------------------------ utils */
SR_FN double sr_now_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec * 1e3 + (double)t.tv_nsec * 1e-6;
}

static int sr__cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Median of v[0..n-1] (sorts v). */
SR_FN double sr_median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, sr__cmp_double);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

SR_FN double sr_min(const double *v, int n)
{
    double m = v[0];
    int i;
    for (i = 1; i < n; ++i) m = v[i] < m ? v[i] : m;
    return m;
}

/* The number of runs: the environment variable `name` when it holds a
   positive integer, else `fallback`. */
SR_FN int sr_runs_from_env(const char *name, int fallback)
{
    const char *s = getenv(name);
    long n = s ? strtol(s, NULL, 10) : 0;
    return n > 0 && n < 1000 ? (int)n : fallback;
}

SR_FN double sr_wrap_angle(double a)
{
    a = fmod(a, 2 * SR_PI);
    if (a > SR_PI) a -= 2 * SR_PI;
    if (a <= -SR_PI) a += 2 * SR_PI;
    return a;
}

static ga2d_vec sr__vec(double x, double y) { return ga2d_vec_make((ga2d_real)x, (ga2d_real)y); }

/* What one run reports. */
typedef struct sr_result {
    double ms;        /* ms per ga2d_world_step after the warm-up */
    double run_ms;    /* ms of every ga2d_world_step but the first, summed: Box2D's
                         benchmark's measure (its benchmark/main.c; scenes.h scenes) */
    double figure;    /* the scene's accuracy figure */
    double contacts;  /* contacts the timed steps solved, per step (mean; counters.constraint_count) */
    double joints;    /* joints the timed steps solved, per step (mean; counters.joints_solved) */
    double joint_gap; /* a scene with joints: the worst separation at the end, m (bench_scene_joint_gap) */
    int ok;           /* built, every step GA2D_OK, figure finite */
} sr_result;

/* --------------------------------------------------------- scenes.h scenes */
/* The scene's own gravity and sleep switch on top of `base`. */
SR_FN ga2d_world_def sr_scene_def(const bench_scene *s, ga2d_world_def base)
{
    base.gravity = sr__vec(s->gx, s->gy);
    base.enable_sleep = s->sleep;
    return base;
}

static ga2d_body_def sr__body_def(const bench_body *b, int fixed_rotation)
{
    ga2d_body_def d = ga2d_default_body_def();
    d.type = b->type == BENCH_DYNAMIC     ? GA2D_BODY_DYNAMIC
             : b->type == BENCH_KINEMATIC ? GA2D_BODY_KINEMATIC
                                          : GA2D_BODY_STATIC;
    d.position = sr__vec(b->x, b->y);
    if (b->angle != 0) d.rotor = ga2d_rotor_from_angle((ga2d_real)b->angle);
    if (b->shape_count == 0 && b->hx > 0) d.polygon = ga2d_polygon_box((ga2d_real)b->hx, (ga2d_real)b->hy);
    d.velocity = sr__vec(b->vx, b->vy);
    d.angular_velocity = (ga2d_real)b->w;
    d.density = (ga2d_real)b->density;
    d.friction = (ga2d_real)b->friction;
    d.linear_damping = (ga2d_real)b->linear_damping;
    d.is_awake = !b->asleep;
    d.fixed_rotation = fixed_rotation && d.type == GA2D_BODY_DYNAMIC;
    return d;
}

/* Shape sh on body id; 0 when ga2d refuses it.  Built with
   BENCH_BOXES_ONLY (for a header from before shapes: the box scenes
   only, see ab_header.sh), every shape is refused. */
static int sr__add_shape(ga2d_world *w, ga2d_body_id id, const bench_shape *sh)
{
#ifdef BENCH_BOXES_ONLY
    (void)w;
    (void)id;
    (void)sh;
    return 0;
#else
    ga2d_shape_def d = ga2d_default_shape_def();
    ga2d_shape_id made = ga2d_shape_id_null();
    d.density = (ga2d_real)sh->density;
    d.friction = (ga2d_real)sh->friction;
    d.restitution = (ga2d_real)sh->restitution;
    d.filter.category_bits = sh->category;
    d.filter.mask_bits = sh->mask;
    d.filter.group_index = sh->group;
    if (sh->kind == BENCH_SHAPE_CIRCLE) {
        ga2d_circle c;
        c.center = sr__vec(sh->x1, sh->y1);
        c.radius = (ga2d_real)sh->radius;
        made = ga2d_shape_create_circle(w, id, &d, &c);
    } else if (sh->kind == BENCH_SHAPE_CAPSULE) {
        ga2d_capsule c;
        c.center1 = sr__vec(sh->x1, sh->y1);
        c.center2 = sr__vec(sh->x2, sh->y2);
        c.radius = (ga2d_real)sh->radius;
        made = ga2d_shape_create_capsule(w, id, &d, &c);
    } else if (sh->kind == BENCH_SHAPE_POLYGON) {
        ga2d_vec pts[BENCH_MAX_VERTICES];
        ga2d_polygon p;
        int i;
        for (i = 0; i < sh->count && i < BENCH_MAX_VERTICES; ++i) pts[i] = sr__vec(sh->px[i], sh->py[i]);
        if (ga2d_polygon_make(pts, sh->count, &p) != GA2D_OK) return 0;
        p.radius = (ga2d_real)sh->radius;
        made = ga2d_shape_create_polygon(w, id, &d, &p);
    }
    return !ga2d_shape_id_is_null(made);
#endif
}

/* The scene's chain loop on body id (scenes.h winds it clockwise, solid
   to the right; a ga2d segment pushes to its left, so the points go in
   backwards); 0 when ga2d refuses it or out of memory. */
static int sr__add_chain(ga2d_world *w, ga2d_body_id id, const bench_scene *s)
{
#ifdef BENCH_BOXES_ONLY
    (void)w;
    (void)id;
    (void)s;
    return 0;
#else
    ga2d_chain_def d = ga2d_default_chain_def();
    ga2d_vec *pts = (ga2d_vec *)malloc((size_t)s->chain_count * sizeof *pts);
    int i, ok;
    if (!pts) return 0;
    for (i = 0; i < s->chain_count; ++i)
        pts[i] = sr__vec(s->chain_x[s->chain_count - 1 - i], s->chain_y[s->chain_count - 1 - i]);
    d.points = pts;
    d.count = s->chain_count;
    d.is_loop = 1;
    d.friction = (ga2d_real)s->chain_friction;
    ok = ga2d_chain_create(w, id, &d).index1 != 0; /* zero: the null id */
    free(pts);
    return ok;
#endif
}

/* Body i of s in w: its box, or a body with its own shapes (and the
   scene's chain, when it is the chain's body); the null id when ga2d
   refuses it.  ga2d has no per-body sleep switch, so never_sleeps is
   not modelled (spinner's bar turns at 5 rad/s and never rests). */
static ga2d_body_id sr__make_body(ga2d_world *w, const bench_scene *s, int i, int fixed_rotation)
{
    const bench_body *b = &s->bodies[i];
    ga2d_body_def d = sr__body_def(b, fixed_rotation);
    ga2d_body_id id = ga2d_body_create(w, &d);
    int k;
    for (k = 0; k < b->shape_count && !ga2d_body_id_is_null(id); ++k)
        if (!sr__add_shape(w, id, &s->shapes[b->shape_first + k])) id = ga2d_body_id_null();
    if (s->chain_count > 0 && i == s->chain_body && !ga2d_body_id_is_null(id) && !sr__add_chain(w, id, s))
        id = ga2d_body_id_null();
    return id;
}

/* The scene's joints in w, in list order, between the bodies ids; 0 when
   ga2d refuses one.  Built with BENCH_BOXES_ONLY (a header from before
   joints), a scene with joints is refused. */
static int sr__make_joints(ga2d_world *w, const bench_scene *s, const ga2d_body_id *ids)
{
#ifdef BENCH_BOXES_ONLY
    (void)w;
    (void)ids;
    return s->joint_count == 0;
#else
    int i;
    for (i = 0; i < s->joint_count; ++i) {
        const bench_joint *j = &s->joints[i];
        ga2d_revolute_joint_def d = ga2d_default_revolute_joint_def();
        d.body_a = ids[j->a];
        d.body_b = ids[j->b];
        d.local_anchor_a = sr__vec(j->ax, j->ay);
        d.local_anchor_b = sr__vec(j->bx, j->by);
        d.enable_motor = j->motor;
        d.motor_speed = (ga2d_real)j->motor_speed;
        d.max_motor_torque = (ga2d_real)j->max_motor_torque;
        if (ga2d_joint_id_is_null(ga2d_revolute_joint_create(w, &d))) return 0;
    }
    return 1;
#endif
}

/* Joints the last step solved (0 in a header from before joints). */
static int sr__joints_solved(const ga2d_world *w)
{
#ifdef BENCH_BOXES_ONLY
    (void)w;
    return 0;
#else
    return ga2d_world_get_counters(w).joints_solved;
#endif
}

/* The worst joint separation of s in w at the end of a run, m (0 without
   joints; NaN when out of memory). */
static double sr__joint_gap(const ga2d_world *w, const bench_scene *s, const ga2d_body_id *ids)
{
    double *pose, gap;
    int i;
    if (s->joint_count == 0) return 0;
    pose = (double *)malloc((size_t)s->count * 3 * sizeof *pose);
    if (!pose) return (double)NAN;
    for (i = 0; i < s->count; ++i) {
        ga2d_vec p = ga2d_body_position(w, ids[i]);
        pose[i] = (double)p.x;
        pose[s->count + i] = (double)p.y;
        pose[2 * s->count + i] = (double)ga2d_body_angle(w, ids[i]);
    }
    gap = bench_scene_joint_gap(s, pose, pose + s->count, pose + 2 * s->count);
    free(pose);
    return gap;
}

/* Sum of m v over the dynamic bodies alive, in double. */
static void sr__momentum(const ga2d_world *w, const bench_scene *s, const ga2d_body_id *ids, double p[2])
{
    int i;
    p[0] = p[1] = 0;
    for (i = 0; i < s->count; ++i) {
        ga2d_vec v;
        double m;
        if (s->bodies[i].type != BENCH_DYNAMIC || ga2d_body_id_is_null(ids[i])) continue;
        v = ga2d_body_velocity(w, ids[i]);
        m = (double)ga2d_body_mass_data(w, ids[i]).mass;
        p[0] += m * (double)v.x;
        p[1] += m * (double)v.y;
    }
}

/* 1 when body b (alive as id) is bounded and its centre is through its
   floor: below lo_y, between lo_x and hi_x (or not finite). */
static int sr__through(const ga2d_world *w, const bench_body *b, ga2d_body_id id)
{
    ga2d_vec c;
    double x, y;
    if (!b->bounded || b->type != BENCH_DYNAMIC) return 0;
    c = ga2d_body_center(w, id);
    x = (double)c.x;
    y = (double)c.y;
    return !(y >= b->lo_y || x < b->lo_x || x > b->hi_x);
}

/* The deepest penetration among the touching contacts, m (0 if none).
   The manifolds are the ones the last step computed at its start, so this
   sees the state after the step before; over a run only the final state
   goes unseen.  *buf grows as needed. */
static double sr__deepest(const ga2d_world *w, ga2d_contact_data **buf, int *cap)
{
    int n = ga2d_world_get_contacts(w, *buf, *cap), i, k;
    double deepest = 0;
    if (n > *cap) {
        ga2d_contact_data *grown = (ga2d_contact_data *)realloc(*buf, (size_t)n * 2 * sizeof **buf);
        if (!grown) return (double)NAN;
        *buf = grown;
        *cap = n * 2;
        n = ga2d_world_get_contacts(w, *buf, *cap);
    }
    for (i = 0; i < n; ++i)
        for (k = 0; k < (*buf)[i].manifold.count; ++k) {
            double d = -(double)(*buf)[i].manifold.points[k].separation;
            if (d > deepest) deepest = d;
        }
    return deepest;
}

/* A body's death: the step before which it goes, and its index. */
typedef struct sr__death { int step, index; } sr__death;

static int sr__cmp_death(const void *a, const void *b)
{
    const sr__death *x = (const sr__death *)a, *y = (const sr__death *)b;
    if (x->step != y->step) return (x->step > y->step) - (x->step < y->step);
    return (x->index > y->index) - (x->index < y->index);
}

/* One run of scene s in a world made from wd (the caller sets gravity and
   sleep, see sr_scene_def): every dynamic body fixed_rotation if asked;
   the tumbler's kinematic walls given, before every step, the velocity
   that turns them about the pivot from where they are; bodies destroyed
   and made before the steps the scene says (deaths first, in order of
   index; then births, in order), none of it timed.  Returns out->ok. */
SR_FN int sr_run_scene(const bench_scene *s, ga2d_world_def wd, int fixed_rotation, sr_result *out)
{
    ga2d_world *w = ga2d_world_create(&wd);
    ga2d_body_id *ids = (ga2d_body_id *)malloc((size_t)(s->count > 0 ? s->count : 1) * sizeof *ids);
    sr__death *deaths = (sr__death *)malloc((size_t)(s->count > 0 ? s->count : 1) * sizeof *deaths);
    ga2d_contact_data *contacts = NULL;
    const ga2d_real dt = (ga2d_real)s->dt;
    double p0[2] = {0, 0}, total = 0, run_ms = 0, deepest = 0, contacts_solved = 0, joints_solved = 0, angle = 0,
           turn = 0;
    ga2d_vec start = ga2d_vec_make(0, 0);
    int i, k, capacity = 0, born = 0, dead = 0, dying = 0, through = 0, ok = w != NULL && ids != NULL && deaths != NULL;
    memset(out, 0, sizeof *out);
    for (i = 0; ok && i < s->count; ++i) {
        ids[i] = ga2d_body_id_null();
        if (s->bodies[i].death > 0) {
            deaths[dying].step = s->bodies[i].death;
            deaths[dying++].index = i;
        }
        ok = i == 0 || s->bodies[i].birth >= s->bodies[i - 1].birth; /* listed in order of birth */
    }
    if (ok) qsort(deaths, (size_t)dying, sizeof *deaths, sr__cmp_death);
    for (; ok && born < s->count && s->bodies[born].birth <= 0; ++born) {
        ids[born] = sr__make_body(w, s, born, fixed_rotation);
        ok = !ga2d_body_id_is_null(ids[born]);
    }
    /* joints join bodies made with the world (scenes.h) */
    if (ok) ok = sr__make_joints(w, s, ids);
    if (ok && (s->figure == BENCH_FIG_DRIFT || s->figure == BENCH_FIG_SAG)) start = ga2d_body_center(w, ids[s->probe]);
    if (ok && s->figure == BENCH_FIG_LAG) angle = (double)ga2d_body_angle(w, ids[s->probe]);
    if (ok && s->figure == BENCH_FIG_MOMENTUM) sr__momentum(w, s, ids, p0);
    for (k = 0; ok && k < s->steps; ++k) {
        double t0, step_ms;
        ga2d_result r;
        for (; ok && dead < dying && deaths[dead].step <= k; ++dead) {
            ga2d_body_id *id = &ids[deaths[dead].index];
            if (ga2d_body_id_is_null(*id)) continue;
            through += sr__through(w, &s->bodies[deaths[dead].index], *id);
            ok = ga2d_body_destroy(w, *id) == GA2D_OK;
            *id = ga2d_body_id_null();
        }
        for (; ok && born < s->count && s->bodies[born].birth <= k; ++born) {
            ids[born] = sr__make_body(w, s, born, fixed_rotation);
            ok = !ga2d_body_id_is_null(ids[born]);
        }
        for (i = 0; i < born; ++i)
            if (s->bodies[i].type == BENCH_KINEMATIC && !ga2d_body_id_is_null(ids[i])) {
                ga2d_vec c = ga2d_body_center(w, ids[i]);
                double vx, vy;
                bench_scene_kinematic_velocity(s, (double)c.x, (double)c.y, &vx, &vy);
                ga2d_body_set_velocity(w, ids[i], sr__vec(vx, vy));
                ga2d_body_set_angular_velocity(w, ids[i], (ga2d_real)s->pivot_w);
            }
        if (!ok) break;
        t0 = sr_now_ms();
        r = ga2d_world_step(w, dt);
        step_ms = sr_now_ms() - t0;
        if (k >= 1) run_ms += step_ms;
        if (k >= SR_WARMUP) {
            total += step_ms;
            contacts_solved += ga2d_world_get_counters(w).constraint_count;
            joints_solved += sr__joints_solved(w);
        }
        ok = r == GA2D_OK;
        if (s->figure == BENCH_FIG_PENETRATION) {
            double d = sr__deepest(w, &contacts, &capacity);
            if (!(d <= deepest)) deepest = d; /* a NaN sticks */
        }
        if (s->figure == BENCH_FIG_LAG) {
            double now = (double)ga2d_body_angle(w, ids[s->probe]);
            turn += bench_scene_turn(angle, now);
            angle = now;
        }
    }
    if (ok) {
        out->ms = total / (s->steps - SR_WARMUP);
        out->run_ms = run_ms;
        out->contacts = contacts_solved / (s->steps - SR_WARMUP);
        out->joints = joints_solved / (s->steps - SR_WARMUP);
        out->joint_gap = sr__joint_gap(w, s, ids);
        if (s->figure == BENCH_FIG_DRIFT) {
            ga2d_vec c = ga2d_body_center(w, ids[s->probe]);
            out->figure = hypot((double)c.x - (double)start.x, (double)c.y - (double)start.y);
        } else if (s->figure == BENCH_FIG_SAG) {
            out->figure = (double)start.y - (double)ga2d_body_center(w, ids[s->probe]).y;
        } else if (s->figure == BENCH_FIG_MOMENTUM) {
            double p[2];
            sr__momentum(w, s, ids, p);
            out->figure = hypot(p[0] - p0[0], p[1] - p0[1]) / hypot(p0[0], p0[1]);
        } else if (s->figure == BENCH_FIG_THROUGH) {
            for (i = 0; i < born; ++i)
                if (!ga2d_body_id_is_null(ids[i])) through += sr__through(w, &s->bodies[i], ids[i]);
            out->figure = through;
        } else if (s->figure == BENCH_FIG_LAG) {
            out->figure = bench_scene_lag(s, turn);
        } else {
            out->figure = deepest;
        }
        ok = isfinite(out->figure) && isfinite(out->joint_gap);
    }
    out->ok = ok;
    free(contacts);
    free(deaths);
    free(ids);
    if (w) ga2d_world_destroy(w);
    return ok;
}

/* ------------------------------------------------------ closed-form scenes */
/* One body each, dt = 1/60, knobs from the world def given (gravity set
   here):
     bounce      a 1 m box dropped flat from a gap of 2 m onto a static
                 ground, restitution 0.5: the n-th apex is e^(2n) h0; the
                 figure is the worst |apex / e^(2n) h0 - 1| over the first
                 3 (1 for each bounce not made within 4 s);
     oscillator  F = -k x, k = m (2 pi)^2: x(t) = cos(2 pi t) from rest at
                 1 m, 10 s, no gravity; the largest distance from it, m;
     spin        10 rad/s, no force, 10 s; |angle - w t| wrapped, rad;
     projectile  launched at (3, 10) m/s under gravity (0, -10), 2 s;
                 |x - (v0 t + g t^2 / 2)|, m. */
enum { SR_BOUNCE, SR_OSCILLATOR, SR_SPIN, SR_PROJECTILE, SR_CLOSED_FORM_COUNT };

static const char *const sr_closed_form_name[SR_CLOSED_FORM_COUNT] = {"bounce", "oscillator", "spin", "projectile"};
static const char *const sr_closed_form_figure[SR_CLOSED_FORM_COUNT] = {
    "worst |apex/e^2n h0 - 1|", "max position error (m)", "angle error (rad)", "position error (m)"};
static const int sr_closed_form_bodies[SR_CLOSED_FORM_COUNT] = {2, 1, 1, 1};
static const int sr_closed_form_steps[SR_CLOSED_FORM_COUNT] = {240, 600, 600, 120};

#define SR_BOUNCE_H0 2.0
#define SR_BOUNCE_E 0.5
#define SR_BOUNCES 3
#define SR_SPIN_W 10.0
#define SR_G 10.0

/* The oscillator's field: the force callback's context. */
typedef struct sr_field {
    ga2d_body_id body;
    ga2d_real k;
} sr_field;

static void sr__spring(ga2d_world *w, void *ctx)
{
    const sr_field *f = (const sr_field *)ctx;
    ga2d_body_apply_force_to_center(w, f->body, ga2d_vec_scale(ga2d_body_center(w, f->body), -f->k));
}

/* The world of closed-form scene `kind`; f (which must outlive the world)
   gets its body. */
static ga2d_world *sr__closed_form_world(int kind, ga2d_world_def wd, sr_field *f)
{
    ga2d_body_def bd = ga2d_default_body_def();
    ga2d_world *w;
    bd.polygon = ga2d_polygon_box((ga2d_real)0.5, (ga2d_real)0.5); /* a 1 m box, density 1: m = 1 */
    wd.gravity = sr__vec(0, kind == SR_BOUNCE || kind == SR_PROJECTILE ? -SR_G : 0);
    if (kind == SR_OSCILLATOR) {
        f->k = (ga2d_real)(4 * SR_PI * SR_PI);
        wd.force_callback = sr__spring;
        wd.force_context = f;
    }
    w = ga2d_world_create(&wd);
    if (!w) return NULL;
    if (kind == SR_BOUNCE) {
        bd.position = sr__vec(0, -1); /* the ground's top face is y = 0 */
        bd.polygon = ga2d_polygon_box(100, 1);
        if (ga2d_body_id_is_null(ga2d_body_create(w, &bd))) {
            ga2d_world_destroy(w);
            return NULL;
        }
        bd = ga2d_default_body_def();
        bd.polygon = ga2d_polygon_box((ga2d_real)0.5, (ga2d_real)0.5);
        bd.position = sr__vec(0, 0.5 + SR_BOUNCE_H0);
        bd.restitution = (ga2d_real)SR_BOUNCE_E;
    } else if (kind == SR_OSCILLATOR) {
        bd.position = sr__vec(1, 0);
    } else if (kind == SR_SPIN) {
        bd.angular_velocity = (ga2d_real)SR_SPIN_W;
    } else {
        bd.velocity = sr__vec(3, 10);
    }
    bd.type = GA2D_BODY_DYNAMIC;
    f->body = ga2d_body_create(w, &bd);
    if (ga2d_body_id_is_null(f->body)) {
        ga2d_world_destroy(w);
        return NULL;
    }
    return w;
}

/* The top of a flight from three consecutive step samples y0, y1, y2:
   in free flight under constant gravity each integrator here puts the
   samples on one parabola (symplectic Euler's too, of slope half a kick
   behind its velocity), so its vertex is the apex, whichever integrator
   ran, with no sampling error. */
static double sr__apex(double y0, double y1, double y2)
{
    double curvature = y0 - 2 * y1 + y2;
    return curvature < 0 ? y1 - (y2 - y0) * (y2 - y0) / (8 * curvature) : y1;
}

/* The bounce's figure from the box's bottom y[0..n] after each step: a
   flight starts at the first step that rises (the collision acts at the
   start of a step, so that step's end is already in flight) and ends at
   the next one that rises again; its apex comes from three samples inside
   it around the top.  A low hop can turn and peak within two steps, so the
   three may lie after the top. */
static double sr__bounce_figure(const double *y, int n)
{
    double figure = 0;
    int k = 1, bounces = 0;
    while (bounces < SR_BOUNCES) {
        int rise, top, end, first;
        double want = pow(SR_BOUNCE_E, 2.0 * (bounces + 1)) * SR_BOUNCE_H0;
        while (k <= n && !(y[k] > y[k - 1])) ++k;
        rise = k;
        while (k <= n && y[k] > y[k - 1]) ++k;
        top = k - 1;
        while (k <= n && !(y[k] > y[k - 1])) ++k;
        end = k;                            /* the next rise, or n + 1 */
        if (rise > n || top >= n) return 1; /* a bounce not made (or not ended) in the run */
        first = top - 1 > rise ? top - 1 : rise;
        if (first + 2 >= end) return 1; /* a hop too short to measure */
        {
            double e = fabs(sr__apex(y[first], y[first + 1], y[first + 2]) / want - 1);
            if (!(e <= figure)) figure = e;
        }
        ++bounces;
        k = end;
    }
    return figure;
}

/* The figure of closed-form scene `kind` under wd; NaN if the world was
   not built or a step failed. */
static double sr__closed_form_figure(int kind, ga2d_world_def wd)
{
    const ga2d_real dt = (ga2d_real)(1.0 / 60);
    const int steps = sr_closed_form_steps[kind];
    sr_field f;
    ga2d_world *w = sr__closed_form_world(kind, wd, &f);
    double figure = 0, *y = (double *)malloc((size_t)(steps + 1) * sizeof *y); /* the box's bottom */
    int n;
    if (!w || !y) {
        free(y);
        if (w) ga2d_world_destroy(w);
        return (double)NAN;
    }
    y[0] = (double)ga2d_body_center(w, f.body).y - 0.5;
    for (n = 1; n <= steps; ++n) {
        double t;
        ga2d_vec c;
        if (ga2d_world_step(w, dt) != GA2D_OK) {
            figure = (double)NAN;
            break;
        }
        t = ga2d_world_time(w);
        c = ga2d_body_center(w, f.body);
        if (kind == SR_BOUNCE) {
            y[n] = (double)c.y - 0.5;
        } else if (kind == SR_OSCILLATOR) {
            double e = hypot((double)c.x - cos(2 * SR_PI * t), (double)c.y);
            if (!(e <= figure)) figure = e; /* a NaN sticks */
        } else if (kind == SR_SPIN) {
            figure = fabs(sr_wrap_angle((double)ga2d_body_angle(w, f.body) - SR_SPIN_W * t));
        } else {
            figure = hypot((double)c.x - 3 * t, (double)c.y - (10 * t - SR_G * t * t / 2));
        }
    }
    if (kind == SR_BOUNCE && n > steps) figure = sr__bounce_figure(y, steps);
    free(y);
    ga2d_world_destroy(w);
    return figure;
}

/* One run of closed-form scene `kind`: its figure, and ms per step timed
   over whole stepping loops (fresh worlds until SR_MIN_TIMED_MS). */
SR_FN int sr_run_closed_form(int kind, ga2d_world_def wd, sr_result *out)
{
    const ga2d_real dt = (ga2d_real)(1.0 / 60);
    const int steps = sr_closed_form_steps[kind];
    double total = 0;
    long timed = 0;
    memset(out, 0, sizeof *out);
    out->figure = sr__closed_form_figure(kind, wd);
    if (!isfinite(out->figure)) return 0;
    while (total < SR_MIN_TIMED_MS) {
        sr_field f;
        ga2d_world *w = sr__closed_form_world(kind, wd, &f);
        double t0;
        int n;
        if (!w) return 0;
        for (n = 0; n < SR_WARMUP; ++n) ga2d_world_step(w, dt);
        t0 = sr_now_ms();
        for (; n < steps; ++n) ga2d_world_step(w, dt);
        total += sr_now_ms() - t0;
        timed += steps - SR_WARMUP;
        ga2d_world_destroy(w);
    }
    out->ms = total / (double)timed;
    out->ok = 1;
    return 1;
}

#endif
