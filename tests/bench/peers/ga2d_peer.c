/* ga2d_peer.c - the ga2d side of `make bench-peers` (see ga2d_peer.h).
   Built as C99 with the library's implementation in this unit only; built
   a second time with -mavx2 -DGA2D_PEER_AVX2 -DGA2D_STATIC (the library's
   functions private to it), its own then named ga2d_peer_avx2_*.  Worlds
   of more than one worker step on a task_pool (examples/task_pool.h,
   whose code the generic build holds for both). */
#define GA2D_IMPLEMENTATION
#include "ga2d_physics.h"
#include "ga2d_peer.h"
#ifndef GA2D_PEER_AVX2
#define TASK_POOL_IMPLEMENTATION
#endif
#include "examples/task_pool.h"
#include <stdio.h>
#include <stdlib.h>

#ifdef GA2D_PEER_AVX2
#define GA2D_PEER_FN(name) ga2d_peer_avx2_##name
#else
#define GA2D_PEER_FN(name) ga2d_peer_##name
#endif

struct ga2d_peer {
    ga2d_world *world;
    task_pool *pool; /* more than one worker: theirs */
    ga2d_body_id *ids;
    int count, capacity;
};

static int ga2d_peer__workers = 1;

void GA2D_PEER_FN(use_workers)(int workers) { ga2d_peer__workers = workers > 1 ? workers : 1; }

ga2d_peer *GA2D_PEER_FN(create)(double gx, double gy, int sleep, int capacity)
{
    ga2d_world_def wd = ga2d_default_world_def();
    ga2d_peer *p = (ga2d_peer *)calloc(1, sizeof *p);
    if (!p) return NULL;
    wd.gravity = ga2d_vec_make((ga2d_real)gx, (ga2d_real)gy);
    wd.enable_sleep = sleep != 0;
    if (ga2d_peer__workers > 1) {
        p->pool = task_pool_create(ga2d_peer__workers);
        if (!p->pool) {
            free(p);
            return NULL;
        }
        wd.worker_count = task_pool_workers(p->pool);
        wd.enqueue_task = task_pool_enqueue;
        wd.finish_task = task_pool_finish;
        wd.user_task_context = p->pool;
    }
    p->world = ga2d_world_create(&wd);
    p->ids = (ga2d_body_id *)malloc((size_t)(capacity > 0 ? capacity : 1) * sizeof *p->ids);
    p->capacity = capacity;
    if (!p->world || !p->ids) {
        GA2D_PEER_FN(destroy)(p);
        return NULL;
    }
    return p;
}

static ga2d_body_type ga2d_peer__type(int type)
{
    /* scenes.h numbers the types static 0, kinematic 1, dynamic 2 */
    return type == 2 ? GA2D_BODY_DYNAMIC : type == 1 ? GA2D_BODY_KINEMATIC : GA2D_BODY_STATIC;
}

int GA2D_PEER_FN(add_box)(ga2d_peer *p, int type, double x, double y, double hx, double hy, double vx, double vy,
                      double w, double density, double friction, int asleep)
{
    ga2d_body_def d = ga2d_default_body_def();
    ga2d_body_id id;
    if (p->count >= p->capacity) return -1;
    d.type = ga2d_peer__type(type);
    d.position = ga2d_vec_make((ga2d_real)x, (ga2d_real)y);
    d.polygon = ga2d_polygon_box((ga2d_real)hx, (ga2d_real)hy);
    d.density = (ga2d_real)density;
    d.friction = (ga2d_real)friction;
    d.restitution = 0;
    if (type != 0) {
        d.velocity = ga2d_vec_make((ga2d_real)vx, (ga2d_real)vy);
        d.angular_velocity = (ga2d_real)w;
    }
    d.is_awake = !asleep;
    id = ga2d_body_create(p->world, &d);
    if (ga2d_body_id_is_null(id)) return -1;
    p->ids[p->count] = id;
    return p->count++;
}

int GA2D_PEER_FN(add_body)(ga2d_peer *p, int type, double x, double y, double angle, double vx, double vy, double w,
                       double linear_damping, int asleep, int never_sleeps)
{
    ga2d_body_def d = ga2d_default_body_def();
    ga2d_body_id id;
    (void)never_sleeps; /* ga2d's sleep is the world's switch only */
    if (p->count >= p->capacity) return -1;
    d.type = ga2d_peer__type(type);
    d.position = ga2d_vec_make((ga2d_real)x, (ga2d_real)y);
    if (angle != 0) d.rotor = ga2d_rotor_from_angle((ga2d_real)angle);
    if (type != 0) {
        d.velocity = ga2d_vec_make((ga2d_real)vx, (ga2d_real)vy);
        d.angular_velocity = (ga2d_real)w;
    }
    d.linear_damping = (ga2d_real)linear_damping;
    d.is_awake = !asleep;
    id = ga2d_body_create(p->world, &d);
    if (ga2d_body_id_is_null(id)) return -1;
    p->ids[p->count] = id;
    return p->count++;
}

int GA2D_PEER_FN(add_shape)(ga2d_peer *p, int i, int kind, double x1, double y1, double x2, double y2, double radius,
                        int count, const double *px, const double *py, double density, double friction,
                        double restitution, int group, unsigned category, unsigned mask)
{
    ga2d_shape_def d = ga2d_default_shape_def();
    ga2d_shape_id made = ga2d_shape_id_null();
    if (i < 0 || i >= p->count) return -1;
    d.density = (ga2d_real)density;
    d.friction = (ga2d_real)friction;
    d.restitution = (ga2d_real)restitution;
    d.filter.group_index = group;
    d.filter.category_bits = category;
    d.filter.mask_bits = mask;
    if (kind == 1) { /* scenes.h's BENCH_SHAPE_CIRCLE */
        ga2d_circle c;
        c.center = ga2d_vec_make((ga2d_real)x1, (ga2d_real)y1);
        c.radius = (ga2d_real)radius;
        made = ga2d_shape_create_circle(p->world, p->ids[i], &d, &c);
    } else if (kind == 2) { /* BENCH_SHAPE_CAPSULE */
        ga2d_capsule c;
        c.center1 = ga2d_vec_make((ga2d_real)x1, (ga2d_real)y1);
        c.center2 = ga2d_vec_make((ga2d_real)x2, (ga2d_real)y2);
        c.radius = (ga2d_real)radius;
        made = ga2d_shape_create_capsule(p->world, p->ids[i], &d, &c);
    } else if (kind == 3 && count > 0 && count <= GA2D_MAX_POLYGON_VERTICES) { /* BENCH_SHAPE_POLYGON */
        ga2d_vec pts[GA2D_MAX_POLYGON_VERTICES];
        ga2d_polygon poly;
        int k;
        for (k = 0; k < count; ++k) pts[k] = ga2d_vec_make((ga2d_real)px[k], (ga2d_real)py[k]);
        if (ga2d_polygon_make(pts, count, &poly) != GA2D_OK) return -1;
        poly.radius = (ga2d_real)radius;
        made = ga2d_shape_create_polygon(p->world, p->ids[i], &d, &poly);
    }
    return ga2d_shape_id_is_null(made) ? -1 : 0;
}

int GA2D_PEER_FN(add_chain_loop)(ga2d_peer *p, int i, int count, const double *x, const double *y, double friction)
{
    ga2d_chain_def d = ga2d_default_chain_def();
    ga2d_vec *pts;
    int k, ok;
    if (i < 0 || i >= p->count || count < 3) return -1;
    pts = (ga2d_vec *)malloc((size_t)count * sizeof *pts);
    if (!pts) return -1;
    /* given clockwise (solid to the right); a ga2d segment pushes to its
       left, so backwards */
    for (k = 0; k < count; ++k) pts[k] = ga2d_vec_make((ga2d_real)x[count - 1 - k], (ga2d_real)y[count - 1 - k]);
    d.points = pts;
    d.count = count;
    d.is_loop = 1;
    d.friction = (ga2d_real)friction;
    ok = ga2d_chain_create(p->world, p->ids[i], &d).index1 != 0; /* zero: the null id */
    free(pts);
    return ok ? 0 : -1;
}

int GA2D_PEER_FN(add_revolute)(ga2d_peer *p, int a, int b, double ax, double ay, double bx, double by, int motor,
                           double motor_speed, double max_motor_torque)
{
    ga2d_revolute_joint_def d = ga2d_default_revolute_joint_def();
    if (a < 0 || b < 0 || a >= p->count || b >= p->count) return -1;
    d.body_a = p->ids[a];
    d.body_b = p->ids[b];
    d.local_anchor_a = ga2d_vec_make((ga2d_real)ax, (ga2d_real)ay);
    d.local_anchor_b = ga2d_vec_make((ga2d_real)bx, (ga2d_real)by);
    d.enable_motor = motor;
    d.motor_speed = (ga2d_real)motor_speed;
    d.max_motor_torque = (ga2d_real)max_motor_torque;
    return ga2d_joint_id_is_null(ga2d_revolute_joint_create(p->world, &d)) ? -1 : 0;
}

int GA2D_PEER_FN(step)(ga2d_peer *p, double dt)
{
    return (int)ga2d_world_step(p->world, (ga2d_real)dt);
}

void GA2D_PEER_FN(pose)(const ga2d_peer *p, int i, double *x, double *y, double *angle)
{
    /* the body's origin (a box's centre; the scenes' bodies with shapes
       are placed by their origin) */
    ga2d_vec c = ga2d_body_position(p->world, p->ids[i]);
    *x = (double)c.x;
    *y = (double)c.y;
    *angle = (double)ga2d_body_angle(p->world, p->ids[i]);
}

void GA2D_PEER_FN(velocity)(const ga2d_peer *p, int i, double *vx, double *vy)
{
    ga2d_vec v = ga2d_body_velocity(p->world, p->ids[i]);
    *vx = (double)v.x;
    *vy = (double)v.y;
}

int GA2D_PEER_FN(is_awake)(const ga2d_peer *p, int i)
{
    return ga2d_body_is_awake(p->world, p->ids[i]);
}

void GA2D_PEER_FN(set_velocity)(ga2d_peer *p, int i, double vx, double vy, double w)
{
    ga2d_body_set_velocity(p->world, p->ids[i], ga2d_vec_make((ga2d_real)vx, (ga2d_real)vy));
    ga2d_body_set_angular_velocity(p->world, p->ids[i], (ga2d_real)w);
}

void GA2D_PEER_FN(destroy)(ga2d_peer *p)
{
    if (!p) return;
    if (p->world) ga2d_world_destroy(p->world);
    task_pool_destroy(p->pool); /* after the world: no step runs on it now */
    free(p->ids);
    free(p);
}

const char *GA2D_PEER_FN(compiler)(void)
{
#if defined(__clang__)
    return "clang " __clang_version__;
#elif defined(__GNUC__)
    return "gcc " __VERSION__;
#else
    return "unknown C compiler";
#endif
}

int GA2D_PEER_FN(real_is_double)(void)
{
    return sizeof(ga2d_real) == sizeof(double);
}

const char *GA2D_PEER_FN(settings)(void)
{
    /* read back from the defaults, so the line cannot go stale */
    static char line[200];
    ga2d_world_def d = ga2d_default_world_def();
    snprintf(line, sizeof line, "ga2d_default_world_def(): %s, %d substeps, contacts %g Hz, damping ratio %g",
             d.solver == GA2D_SOLVER_SOFT_STEP ? "soft step" : "PGS", d.substeps, (double)d.contact_hertz,
             (double)d.contact_damping_ratio);
    return line;
}
