/* ga2d_peer.c - the ga2d side of `make bench-peers` (see ga2d_peer.h).
   Built as C99 with the library's implementation in this unit only; built
   a second time with -mavx2 -DGA2D_PEER_AVX2 -DGA2D_STATIC (the library's
   functions private to it), its own then named ga2d_peer_avx2_*. */
#define GA2D_IMPLEMENTATION
#include "ga2d_physics.h"
#include "ga2d_peer.h"
#include <stdio.h>
#include <stdlib.h>

#ifdef GA2D_PEER_AVX2
#define GA2D_PEER_FN(name) ga2d_peer_avx2_##name
#else
#define GA2D_PEER_FN(name) ga2d_peer_##name
#endif

struct ga2d_peer {
    ga2d_world *world;
    ga2d_body_id *ids;
    int count, capacity;
};

ga2d_peer *GA2D_PEER_FN(create)(double gx, double gy, int sleep, int capacity)
{
    ga2d_world_def wd = ga2d_default_world_def();
    ga2d_peer *p = (ga2d_peer *)calloc(1, sizeof *p);
    if (!p) return NULL;
    wd.gravity = ga2d_vec_make((ga2d_real)gx, (ga2d_real)gy);
    wd.enable_sleep = sleep != 0;
    p->world = ga2d_world_create(&wd);
    p->ids = (ga2d_body_id *)malloc((size_t)(capacity > 0 ? capacity : 1) * sizeof *p->ids);
    p->capacity = capacity;
    if (!p->world || !p->ids) {
        GA2D_PEER_FN(destroy)(p);
        return NULL;
    }
    return p;
}

int GA2D_PEER_FN(add_box)(ga2d_peer *p, int type, double x, double y, double hx, double hy, double vx, double vy,
                      double w, double density, double friction, int asleep)
{
    ga2d_body_def d = ga2d_default_body_def();
    ga2d_body_id id;
    if (p->count >= p->capacity) return -1;
    /* scenes.h numbers the types static 0, kinematic 1, dynamic 2 */
    d.type = type == 2 ? GA2D_BODY_DYNAMIC : type == 1 ? GA2D_BODY_KINEMATIC : GA2D_BODY_STATIC;
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

int GA2D_PEER_FN(add_circle)(ga2d_peer *p, int type, double x, double y, double radius, double density, double friction,
                         unsigned category, unsigned mask)
{
    ga2d_body_def d = ga2d_default_body_def();
    ga2d_shape_def sd = ga2d_default_shape_def();
    ga2d_circle c;
    ga2d_body_id id;
    if (p->count >= p->capacity) return -1;
    d.type = type == 2 ? GA2D_BODY_DYNAMIC : type == 1 ? GA2D_BODY_KINEMATIC : GA2D_BODY_STATIC;
    d.position = ga2d_vec_make((ga2d_real)x, (ga2d_real)y);
    id = ga2d_body_create(p->world, &d);
    if (ga2d_body_id_is_null(id)) return -1;
    sd.density = (ga2d_real)density;
    sd.friction = (ga2d_real)friction;
    sd.restitution = 0;
    sd.filter.category_bits = category;
    sd.filter.mask_bits = mask;
    c.center = ga2d_vec_make(0, 0);
    c.radius = (ga2d_real)radius;
    if (ga2d_shape_id_is_null(ga2d_shape_create_circle(p->world, id, &sd, &c))) return -1;
    p->ids[p->count] = id;
    return p->count++;
}

int GA2D_PEER_FN(add_revolute)(ga2d_peer *p, int a, int b, double ax, double ay, double bx, double by)
{
    ga2d_revolute_joint_def d = ga2d_default_revolute_joint_def();
    if (a < 0 || b < 0 || a >= p->count || b >= p->count) return -1;
    d.body_a = p->ids[a];
    d.body_b = p->ids[b];
    d.local_anchor_a = ga2d_vec_make((ga2d_real)ax, (ga2d_real)ay);
    d.local_anchor_b = ga2d_vec_make((ga2d_real)bx, (ga2d_real)by);
    return ga2d_joint_id_is_null(ga2d_revolute_joint_create(p->world, &d)) ? -1 : 0;
}

int GA2D_PEER_FN(step)(ga2d_peer *p, double dt)
{
    return (int)ga2d_world_step(p->world, (ga2d_real)dt);
}

void GA2D_PEER_FN(pose)(const ga2d_peer *p, int i, double *x, double *y, double *angle)
{
    /* boxes and circles are centred on their origin, so origin = centre */
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
