/* b2v3_peer.c - the Box2D v3 side of `make bench-peers B2V3_SRC=...` (see
   ga2d_peer.h).  Compiled as C17 against the headers of the Box2D v3
   source tree given (-I$(B2V3_SRC)/include) and linked with the library
   peers.mk builds from that tree into build/; nothing of Box2D v3 is in
   this project.  Its world is b2DefaultWorldDef() with the scene's gravity
   and sleep switch and one worker (no task system: the step runs on the
   calling thread), or more on its built-in scheduler (use_workers),
   stepped with 4 substeps as its benchmark does; shapes are made through
   its public API only. */
#include "box2d/box2d.h"
#include "ga2d_peer.h"
#include <stdio.h>
#include <stdlib.h>

/* Box2D v3's benchmark steps at 1/60 s with 4 substeps (benchmark/main.c) */
#define B2V3_PEER_SUBSTEPS 4

struct b2v3_peer {
    b2WorldId world;
    b2BodyId *ids;
    int count, capacity;
};

static b2Vec2 b2v3_peer__vec(double x, double y)
{
    b2Vec2 v;
    v.x = (float)x;
    v.y = (float)y;
    return v;
}

static b2BodyType b2v3_peer__type(int type)
{
    /* scenes.h numbers the types static 0, kinematic 1, dynamic 2 */
    return type == 2 ? b2_dynamicBody : type == 1 ? b2_kinematicBody : b2_staticBody;
}

static int b2v3_peer__workers = 1;

void b2v3_peer_use_workers(int workers) { b2v3_peer__workers = workers > 1 ? workers : 1; }

b2v3_peer *b2v3_peer_create(double gx, double gy, int sleep, int capacity)
{
    b2WorldDef wd = b2DefaultWorldDef();
    b2v3_peer *p = (b2v3_peer *)calloc(1, sizeof *p);
    if (!p) return NULL;
    wd.gravity = b2v3_peer__vec(gx, gy);
    wd.enableSleep = sleep != 0;
    wd.workerCount = b2v3_peer__workers; /* more than one: its own scheduler's threads */
    p->world = b2CreateWorld(&wd);
    p->ids = (b2BodyId *)malloc((size_t)(capacity > 0 ? capacity : 1) * sizeof *p->ids);
    p->capacity = capacity;
    if (!p->ids) {
        b2v3_peer_destroy(p);
        return NULL;
    }
    return p;
}

int b2v3_peer_add_body(b2v3_peer *p, int type, double x, double y, double angle, double vx, double vy, double w,
                       double linear_damping, int asleep, int never_sleeps)
{
    b2BodyDef d = b2DefaultBodyDef();
    if (p->count >= p->capacity) return -1;
    d.type = b2v3_peer__type(type);
    d.position.x = (float)x;
    d.position.y = (float)y;
    d.rotation = b2MakeRot((float)angle);
    if (type != 0) {
        d.linearVelocity = b2v3_peer__vec(vx, vy);
        d.angularVelocity = (float)w;
    }
    d.linearDamping = (float)linear_damping;
    d.isAwake = !asleep;
    d.enableSleep = !never_sleeps;
    p->ids[p->count] = b2CreateBody(p->world, &d);
    return p->count++;
}

int b2v3_peer_add_shape(b2v3_peer *p, int i, int kind, double x1, double y1, double x2, double y2, double radius,
                        int count, const double *px, const double *py, double density, double friction,
                        double restitution, int group, unsigned category, unsigned mask)
{
    b2ShapeDef d = b2DefaultShapeDef();
    if (i < 0 || i >= p->count) return -1;
    d.density = (float)density;
    d.material.friction = (float)friction;
    d.material.restitution = (float)restitution;
    d.filter.groupIndex = group;
    d.filter.categoryBits = category;
    /* the scenes' masks are 32 bits wide; "all" stays all in v3's 64 */
    d.filter.maskBits = mask == 0xFFFFFFFFu ? UINT64_MAX : (uint64_t)mask;
    if (kind == 1) { /* scenes.h's BENCH_SHAPE_CIRCLE */
        b2Circle c;
        c.center = b2v3_peer__vec(x1, y1);
        c.radius = (float)radius;
        b2CreateCircleShape(p->ids[i], &d, &c);
    } else if (kind == 2) { /* BENCH_SHAPE_CAPSULE */
        b2Capsule c;
        c.center1 = b2v3_peer__vec(x1, y1);
        c.center2 = b2v3_peer__vec(x2, y2);
        c.radius = (float)radius;
        b2CreateCapsuleShape(p->ids[i], &d, &c);
    } else if (kind == 3 && count >= 3 && count <= B2_MAX_POLYGON_VERTICES) { /* BENCH_SHAPE_POLYGON */
        b2Vec2 pts[B2_MAX_POLYGON_VERTICES];
        b2Hull hull;
        b2Polygon poly;
        int k;
        for (k = 0; k < count; ++k) pts[k] = b2v3_peer__vec(px[k], py[k]);
        hull = b2ComputeHull(pts, count);
        if (hull.count == 0) return -1;
        poly = b2MakePolygon(&hull, (float)radius);
        b2CreatePolygonShape(p->ids[i], &d, &poly);
    } else {
        return -1;
    }
    return 0;
}

int b2v3_peer_add_box(b2v3_peer *p, int type, double x, double y, double hx, double hy, double vx, double vy, double w,
                      double density, double friction, int asleep)
{
    b2ShapeDef d = b2DefaultShapeDef();
    b2Polygon box = b2MakeBox((float)hx, (float)hy);
    int i = b2v3_peer_add_body(p, type, x, y, 0, vx, vy, w, 0, asleep, 0);
    if (i < 0) return -1;
    d.density = (float)density;
    d.material.friction = (float)friction;
    d.material.restitution = 0;
    b2CreatePolygonShape(p->ids[i], &d, &box);
    return i;
}

int b2v3_peer_add_chain_loop(b2v3_peer *p, int i, int count, const double *x, const double *y, double friction)
{
    b2ChainDef d = b2DefaultChainDef();
    b2SurfaceMaterial material = b2DefaultSurfaceMaterial();
    b2Vec2 *pts;
    int k;
    if (i < 0 || i >= p->count || count < 4) return -1; /* v3 wants 4 points or more */
    pts = (b2Vec2 *)malloc((size_t)count * sizeof *pts);
    if (!pts) return -1;
    /* given clockwise, solid to the right: v3's own winding */
    for (k = 0; k < count; ++k) pts[k] = b2v3_peer__vec(x[k], y[k]);
    material.friction = (float)friction;
    d.points = pts;
    d.count = count;
    d.isLoop = true;
    d.materials = &material;
    d.materialCount = 1;
    b2CreateChain(p->ids[i], &d); /* the points are copied */
    free(pts);
    return 0;
}

int b2v3_peer_add_revolute(b2v3_peer *p, int a, int b, double ax, double ay, double bx, double by, int motor,
                           double motor_speed, double max_motor_torque)
{
    b2RevoluteJointDef d = b2DefaultRevoluteJointDef();
    if (a < 0 || b < 0 || a >= p->count || b >= p->count) return -1;
    d.base.bodyIdA = p->ids[a];
    d.base.bodyIdB = p->ids[b];
    d.base.localFrameA.p = b2v3_peer__vec(ax, ay);
    d.base.localFrameB.p = b2v3_peer__vec(bx, by);
    d.enableMotor = motor != 0;
    d.motorSpeed = (float)motor_speed;
    d.maxMotorTorque = (float)max_motor_torque;
    b2CreateRevoluteJoint(p->world, &d);
    return 0;
}

int b2v3_peer_step(b2v3_peer *p, double dt)
{
    b2World_Step(p->world, (float)dt, B2V3_PEER_SUBSTEPS);
    return 0;
}

void b2v3_peer_pose(const b2v3_peer *p, int i, double *x, double *y, double *angle)
{
    b2Pos c = b2Body_GetPosition(p->ids[i]);
    *x = (double)c.x;
    *y = (double)c.y;
    *angle = (double)b2Rot_GetAngle(b2Body_GetRotation(p->ids[i]));
}

void b2v3_peer_velocity(const b2v3_peer *p, int i, double *vx, double *vy)
{
    b2Vec2 v = b2Body_GetLinearVelocity(p->ids[i]);
    *vx = (double)v.x;
    *vy = (double)v.y;
}

int b2v3_peer_is_awake(const b2v3_peer *p, int i) { return b2Body_IsAwake(p->ids[i]); }

void b2v3_peer_set_velocity(b2v3_peer *p, int i, double vx, double vy, double w)
{
    b2Body_SetLinearVelocity(p->ids[i], b2v3_peer__vec(vx, vy));
    b2Body_SetAngularVelocity(p->ids[i], (float)w);
}

void b2v3_peer_destroy(b2v3_peer *p)
{
    if (!p) return;
    if (b2World_IsValid(p->world)) b2DestroyWorld(p->world);
    free(p->ids);
    free(p);
}

const char *b2v3_peer_compiler(void)
{
#if defined(__clang__)
    return "clang " __clang_version__;
#elif defined(__GNUC__)
    return "gcc " __VERSION__;
#else
    return "unknown C compiler";
#endif
}

int b2v3_peer_real_is_double(void)
{
#ifdef BOX2D_DOUBLE_PRECISION
    return 1;
#else
    return 0;
#endif
}

const char *b2v3_peer_settings(void)
{
    /* read back from the defaults, so the line cannot go stale */
    static char line[300];
    b2WorldDef d = b2DefaultWorldDef();
    b2Version v = b2GetVersion();
    snprintf(line, sizeof line,
             "Box2D %d.%d.%d, b2DefaultWorldDef(): %d substeps, 1 worker (-2w: 2, its scheduler), contacts %g Hz, damping ratio %g, "
             "continuous %s",
             v.major, v.minor, v.revision, B2V3_PEER_SUBSTEPS, (double)d.contactHertz, (double)d.contactDampingRatio,
             d.enableContinuous ? "on" : "off");
    return line;
}
