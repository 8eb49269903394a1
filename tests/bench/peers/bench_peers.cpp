/* bench_peers.cpp - ga2d against Box2D 2.4.1 and Chipmunk 7, and Box2D v3
   when peers.mk is given its sources (B2V3_SRC), on the benchmark scenes
   of tests/bench/scenes.h (`make bench-peers`).

   Every engine builds the same list of bodies: boxes, bodies of their own
   shapes (joint_grid's circles; spinner's capsules, circles, boxes and
   rounded bar), the scene's chain loop and its revolute joints, with
   motors (Box2D's b2RevoluteJoint, Chipmunk's pivot joint; Chipmunk sits
   out scenes with other shapes, a chain or a motor).  ga2d and Box2D v3
   are C units reached through ga2d_peer.h.  For each scene the engines run
   alternately (run r: ga2d, Box2D, Chipmunk, Box2D v3 where built, each
   with a fresh world; then ga2d built with -mavx2, where the CPU has
   AVX2), so a slow spell of the machine hits all of them.  Only the world
   step is timed, and not the first 10 steps (the first broadphase pass and
   warm-up); building, the tumbler's wall velocities and the accuracy
   figure are outside the clock.  Prints a table per scene and writes a CSV.

     peers [scenes] [csv]  scenes: "all" (the default), or scenes.h's names
                           separated by commas (large_pyramid,joint_grid);
                           csv defaults to build/bench/peers.csv.
     BENCH_RUNS=n          runs per engine and scene (default 3).
     PEERS_MAX_RUN_S=s     a run stops once its steps took s seconds (default
                           120); the engine's row says so, with no median.
     PEERS_ENGINES=a,b     runs only the engines named (their names in the
                           tables: ga2d, Box2D, Chipmunk, Box2D-v3, ga2d-2w,
                           Box2D-v3-2w, ga2d-avx2); the others' rows say they
                           were left out, and a ratio against one is nan. */
#include <box2d/box2d.h>
#include <chipmunk/chipmunk.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>
#include <signal.h>
#include <time.h>
#include <unistd.h>

#include "../scenes.h"
#include "ga2d_peer.h"

/* 1 when the Makefile also built ga2d with -mavx2 (the CPU has AVX2) */
#ifndef PEERS_AVX2
#define PEERS_AVX2 0
#endif
/* 1 when the Makefile built Box2D v3 from B2V3_SRC (b2v3_peer.c) */
#ifndef PEERS_B2V3
#define PEERS_B2V3 0
#endif
#ifndef PEERS_B2V3_CFLAGS
#define PEERS_B2V3_CFLAGS ""
#endif
#ifndef PEERS_B2V3_SRC
#define PEERS_B2V3_SRC ""
#endif

/* given by peers.mk: the flags, and Box2D's package version (its 2.4.1
   library still reports b2_version 2.4.0) */
#ifndef PEERS_OPT
#define PEERS_OPT "(not given)"
#endif
#ifndef PEERS_BOX2D_VERSION
#define PEERS_BOX2D_VERSION ""
#endif

static const double kPi = 3.14159265358979323846;
static const int kUntimedSteps = 10;
static const int kBox2dVelocityIterations = 8;
static const int kBox2dPositionIterations = 3;
static const int kChipmunkIterations = 10;
/* Chipmunk's default collision slop (0.1) assumes pixel units; the scenes
   are in metres, so it gets the linear slop the other two use. */
static const double kChipmunkSlop = 0.005;
static const double kChipmunkSleepTime = 0.5;
/* an overlap deeper than 40 % of a tumbler box: counted, as a sign of boxes
   passing through each other */
static const double kDeepOverlap = 0.1;
/* In a scene with joints, a body faster than this has blown up: the run
   stops there and the engine's row says so (not a failure of the runner).
   Four times the speed of a fall from 150 m, sqrt(2 g 150) = 55 m/s: the
   joint grid is 99 m tall and the softest engine stretches it by half.
   (Chipmunk 7's pivot grid passes it at about step 180; its broadphase
   then takes a second a step.) */
static const double kBlownUpSpeed = 200;
/* A run stops once its steps have taken this long (PEERS_MAX_RUN_S, s;
   default 120): Box2D 2.4.1 on spinner would take many minutes a run. */
static double g_max_run_ms = 120e3;

static double now_ms()
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec * 1e3 + (double)t.tv_nsec / 1e6;
}

/* ------------------------------------------------------------- engines */
/* One engine's world of one scene; body i is the scene's body i. */
class World {
public:
    virtual ~World() {}
    virtual bool ok() const = 0;
    virtual bool step(double dt) = 0;
    virtual void pose(int i, double *x, double *y, double *angle) const = 0;
    virtual void velocity(int i, double *vx, double *vy) const = 0;
    virtual void set_velocity(int i, double vx, double vy, double w) = 0; /* kinematic walls */
    virtual bool awake(int i) const = 0;
};

/* The one shape of body b when it is a circle at the body's origin (the
   bodies with shapes Chipmunk's world builds); NULL for a box (no shapes
   of its own) or anything else. */
static const bench_shape *lone_circle(const bench_scene &s, const bench_body &b)
{
    if (b.shape_count != 1) return NULL;
    const bench_shape *sh = &s.shapes[b.shape_first];
    return sh->kind == BENCH_SHAPE_CIRCLE && sh->x1 == 0 && sh->y1 == 0 ? sh : NULL;
}

/* Whether Chipmunk's world builds the scene (else it sits it out): boxes
   and centred circles, pins, no chain and no motor (spinner has both). */
static bool chipmunk_builds(const bench_scene &s)
{
    for (int i = 0; i < s.joint_count; ++i)
        if (s.joints[i].motor) return false;
    for (int i = 0; i < s.count; ++i)
        if (s.bodies[i].shape_count > 0 && !lone_circle(s, s.bodies[i])) return false;
    return s.chain_count == 0;
}

/* A body of shapes: shape_count > 0, or none at all (a chain's body). */
static bool has_own_shapes(const bench_body &b) { return b.shape_count > 0 || b.hx <= 0; }

/* One engine reached through ga2d_peer.h's C functions (T: its world):
   ga2d's generic build, its -mavx2 build, Box2D v3. */
template <class T> struct CBuild {
    T *(*create)(double gx, double gy, int sleep, int capacity);
    int (*add_box)(T *p, int type, double x, double y, double hx, double hy, double vx, double vy, double w,
                   double density, double friction, int asleep);
    int (*add_body)(T *p, int type, double x, double y, double angle, double vx, double vy, double w,
                    double linear_damping, int asleep, int never_sleeps);
    int (*add_shape)(T *p, int i, int kind, double x1, double y1, double x2, double y2, double radius, int count,
                     const double *px, const double *py, double density, double friction, double restitution,
                     int group, unsigned category, unsigned mask);
    int (*add_chain_loop)(T *p, int i, int count, const double *x, const double *y, double friction);
    int (*add_revolute)(T *p, int a, int b, double ax, double ay, double bx, double by, int motor,
                        double motor_speed, double max_motor_torque);
    int (*step)(T *p, double dt);
    void (*pose)(const T *p, int i, double *x, double *y, double *angle);
    void (*velocity)(const T *p, int i, double *vx, double *vy);
    int (*is_awake)(const T *p, int i);
    void (*set_velocity)(T *p, int i, double vx, double vy, double w);
    void (*destroy)(T *p);
};

#define PEER_BUILD(P)                                                                                               \
    {P##create,   P##add_box,  P##add_body,  P##add_shape,     P##add_chain_loop, P##add_revolute,                 \
     P##step,     P##pose,     P##velocity,  P##is_awake,      P##set_velocity,   P##destroy}
static const CBuild<ga2d_peer> kGa2dGeneric = PEER_BUILD(ga2d_peer_);
#if PEERS_AVX2
static const CBuild<ga2d_peer> kGa2dAvx2 = PEER_BUILD(ga2d_peer_avx2_);
#endif
#if PEERS_B2V3
static const CBuild<b2v3_peer> kB2v3 = PEER_BUILD(b2v3_peer_);
#endif

template <class T> class CWorld : public World {
public:
    CWorld(const bench_scene &s, const CBuild<T> &f) : f_(f), p_(f.create(s.gx, s.gy, s.sleep, s.count)), ok_(p_ != NULL)
    {
        for (int i = 0; ok_ && i < s.count; ++i) {
            const bench_body &b = s.bodies[i];
            if (!has_own_shapes(b)) {
                ok_ = f_.add_box(p_, b.type, b.x, b.y, b.hx, b.hy, b.vx, b.vy, b.w, b.density, b.friction, b.asleep) == i;
                continue;
            }
            ok_ = f_.add_body(p_, b.type, b.x, b.y, b.angle, b.vx, b.vy, b.w, b.linear_damping, b.asleep,
                              b.never_sleeps) == i;
            for (int k = 0; ok_ && k < b.shape_count; ++k) {
                const bench_shape &sh = s.shapes[b.shape_first + k];
                ok_ = f_.add_shape(p_, i, sh.kind, sh.x1, sh.y1, sh.x2, sh.y2, sh.radius, sh.count, sh.px, sh.py,
                                   sh.density, sh.friction, sh.restitution, sh.group, sh.category, sh.mask) == 0;
            }
            if (ok_ && s.chain_count > 0 && i == s.chain_body)
                ok_ = f_.add_chain_loop(p_, i, s.chain_count, s.chain_x, s.chain_y, s.chain_friction) == 0;
        }
        for (int i = 0; ok_ && i < s.joint_count; ++i) {
            const bench_joint &j = s.joints[i];
            ok_ = f_.add_revolute(p_, j.a, j.b, j.ax, j.ay, j.bx, j.by, j.motor, j.motor_speed, j.max_motor_torque) == 0;
        }
    }
    ~CWorld() { f_.destroy(p_); }
    bool ok() const { return ok_; }
    bool step(double dt) { return f_.step(p_, dt) == 0; }
    void pose(int i, double *x, double *y, double *angle) const { f_.pose(p_, i, x, y, angle); }
    void velocity(int i, double *vx, double *vy) const { f_.velocity(p_, i, vx, vy); }
    void set_velocity(int i, double vx, double vy, double w) { f_.set_velocity(p_, i, vx, vy, w); }
    bool awake(int i) const { return f_.is_awake(p_, i) != 0; }

private:
    CWorld(const CWorld &);
    CWorld &operator=(const CWorld &);
    const CBuild<T> &f_;
    T *p_;
    bool ok_;
};

/* Box2D 2.4.1 has no capsule and no rounded polygon.  A capsule is built
   as the box between its two centres and a circle at each end, the circles
   at half the density (the box covers half of each), which gives the
   capsule's mass and centre exactly; its rotational inertia is then set to
   the capsule's own (b2Body::SetMassData).  A rounded polygon becomes the
   sharp polygon its rounded outline is inscribed in: each vertex moved out
   to where the two neighbouring edges, pushed out by the radius, meet
   (spinner's bar: a 0.6 x 20.2 box in place of 0.4 x 20 rounded by 0.2,
   the corners 0.083 m further out). */
struct Box2dMass {
    double mass, mx, my, inertia; /* sums over a body's shapes; inertia about the body origin */
};

/* A capsule's mass, centroid and inertia about its centroid, as a solid
   rectangle of length L = |c2 - c1| and width 2r plus two half discs. */
static void capsule_mass(const bench_shape &sh, double *m, double *i_centre)
{
    double L = std::hypot(sh.x2 - sh.x1, sh.y2 - sh.y1), r = sh.radius, rho = sh.density;
    double m_box = rho * 2 * r * L, m_caps = rho * kPi * r * r;
    double h = 0.5 * L, d = 4 * r / (3 * kPi); /* a half disc's centroid from its flat side */
    /* the two half discs about the capsule's centre: m_caps (r^2/2 + h^2 + 2 h d) (parallel axes) */
    double i_caps = m_caps * (0.5 * r * r + h * h + 2 * h * d);
    double i_box = m_box * (L * L + 4 * r * r) / 12;
    *m = m_box + m_caps;
    *i_centre = i_box + i_caps;
}

/* The polygon's vertices pushed out by r: vertex k moves to where the
   edges before and after it, each moved out by r along its outward
   normal, meet: v + r (n1 + n2) / (1 + n1.n2). */
static void inflate_polygon(const bench_shape &sh, b2Vec2 *out)
{
    int n = sh.count;
    for (int k = 0; k < n; ++k) {
        int a = (k + n - 1) % n, b = (k + 1) % n;
        double e1x = sh.px[k] - sh.px[a], e1y = sh.py[k] - sh.py[a], e2x = sh.px[b] - sh.px[k], e2y = sh.py[b] - sh.py[k];
        double l1 = std::hypot(e1x, e1y), l2 = std::hypot(e2x, e2y);
        double n1x = e1y / l1, n1y = -e1x / l1, n2x = e2y / l2, n2y = -e2x / l2; /* outward: counter-clockwise */
        double f = sh.radius / (1 + n1x * n2x + n1y * n2y);
        out[k].Set((float)(sh.px[k] + f * (n1x + n2x)), (float)(sh.py[k] + f * (n1y + n2y)));
    }
}

class Box2dWorld : public World {
public:
    explicit Box2dWorld(const bench_scene &s) : world_(b2Vec2((float)s.gx, (float)s.gy)), ok_(true)
    {
        world_.SetAllowSleeping(s.sleep != 0);
        /* On spinner 2.4.1's continuous collision stalls: one run went
           past 10 minutes with 97 % of the time in b2World::SolveTOI (it
           sweeps every fast body against the loop and repeats after each
           hit), so there it is off; everywhere else it is on, its default */
        world_.SetContinuousPhysics(s.chain_count == 0);
        bodies_.reserve((size_t)s.count);
        for (int i = 0; i < s.count; ++i) {
            const bench_body &b = s.bodies[i];
            b2BodyDef bd;
            bd.type = b.type == BENCH_DYNAMIC ? b2_dynamicBody : b.type == BENCH_KINEMATIC ? b2_kinematicBody : b2_staticBody;
            bd.position.Set((float)b.x, (float)b.y);
            bd.angle = (float)b.angle;
            bd.linearVelocity.Set((float)b.vx, (float)b.vy);
            bd.angularVelocity = (float)b.w;
            bd.linearDamping = (float)b.linear_damping;
            bd.awake = !b.asleep;
            bd.allowSleep = !b.never_sleeps;
            b2Body *body = world_.CreateBody(&bd);
            bodies_.push_back(body);
            if (!has_own_shapes(b)) {
                b2PolygonShape box;
                b2FixtureDef fd;
                box.SetAsBox((float)b.hx, (float)b.hy);
                fd.shape = &box;
                fd.density = (float)b.density;
                fd.friction = (float)b.friction; /* Box2D mixes pairs as sqrt(mu_a mu_b) */
                fd.restitution = 0;
                body->CreateFixture(&fd);
                continue;
            }
            Box2dMass mass = {0, 0, 0, 0};
            bool capsules = false;
            for (int k = 0; k < b.shape_count; ++k) capsules = capsules || add_shape(body, s.shapes[b.shape_first + k], &mass);
            if (capsules && b.type == BENCH_DYNAMIC && mass.mass > 0) {
                b2MassData md;
                md.mass = (float)mass.mass;
                md.center.Set((float)(mass.mx / mass.mass), (float)(mass.my / mass.mass));
                md.I = (float)mass.inertia; /* about the body origin, as Box2D 2.4 takes it */
                body->SetMassData(&md);
            }
            if (s.chain_count > 0 && i == s.chain_body) add_loop(s);
        }
        for (int i = 0; ok_ && i < s.joint_count; ++i) {
            const bench_joint &j = s.joints[i];
            b2RevoluteJointDef jd; /* collideConnected false, no limit */
            jd.bodyA = bodies_[(size_t)j.a];
            jd.bodyB = bodies_[(size_t)j.b];
            jd.localAnchorA.Set((float)j.ax, (float)j.ay);
            jd.localAnchorB.Set((float)j.bx, (float)j.by);
            jd.referenceAngle = jd.bodyB->GetAngle() - jd.bodyA->GetAngle();
            jd.enableMotor = j.motor != 0;
            jd.motorSpeed = (float)j.motor_speed;
            jd.maxMotorTorque = (float)j.max_motor_torque;
            world_.CreateJoint(&jd);
        }
    }
    bool ok() const { return ok_; }
    bool step(double dt)
    {
        world_.Step((float)dt, kBox2dVelocityIterations, kBox2dPositionIterations);
        return true;
    }
    void pose(int i, double *x, double *y, double *angle) const
    {
        const b2Vec2 &p = bodies_[(size_t)i]->GetPosition();
        *x = p.x;
        *y = p.y;
        *angle = bodies_[(size_t)i]->GetAngle();
    }
    void velocity(int i, double *vx, double *vy) const
    {
        const b2Vec2 &v = bodies_[(size_t)i]->GetLinearVelocity();
        *vx = v.x;
        *vy = v.y;
    }
    void set_velocity(int i, double vx, double vy, double w)
    {
        bodies_[(size_t)i]->SetLinearVelocity(b2Vec2((float)vx, (float)vy));
        bodies_[(size_t)i]->SetAngularVelocity((float)w);
    }
    bool awake(int i) const { return bodies_[(size_t)i]->IsAwake(); }

private:
    /* The scene's loop as chain_count static bodies of one one-sided edge
       each, its neighbours' points as the edge's ghosts: the segments a
       b2ChainShape loop makes (clockwise, solid to the right, as 2.4's
       one-sided edges push), on bodies of their own.  On one body, as
       Box2D v3 has it, one spinner run took over 6 minutes: for every
       pair b2ContactManager::AddPair scans the body's contact list, which
       holds every contact of the loop. */
    void add_loop(const bench_scene &s)
    {
        const bench_body &owner = s.bodies[s.chain_body]; /* its points are in this body's frame (unturned) */
        int n = s.chain_count;
        for (int k = 0; k < n; ++k) {
            b2Vec2 v[4];
            for (int e = 0; e < 4; ++e) {
                int m = (k + e - 1 + n) % n;
                v[e].Set((float)(s.chain_x[m] + owner.x), (float)(s.chain_y[m] + owner.y));
            }
            b2BodyDef bd;
            bd.type = b2_staticBody;
            b2Body *body = world_.CreateBody(&bd);
            b2EdgeShape edge;
            edge.SetOneSided(v[0], v[1], v[2], v[3]);
            b2FixtureDef fd;
            fd.shape = &edge;
            fd.friction = (float)s.chain_friction;
            body->CreateFixture(&fd);
        }
    }

    /* One scene shape as fixtures (see inflate_polygon, capsule_mass); adds
       its mass to *m; true for a capsule (the body's mass is then set). */
    static bool add_shape(b2Body *body, const bench_shape &sh, Box2dMass *m)
    {
        b2FixtureDef fd;
        fd.density = (float)sh.density;
        fd.friction = (float)sh.friction;
        fd.restitution = (float)sh.restitution; /* pairs take the larger */
        /* Box2D 2.4's filter bits are 16 wide; the scenes use the low ones */
        fd.filter.categoryBits = (uint16)sh.category;
        fd.filter.maskBits = (uint16)sh.mask;
        fd.filter.groupIndex = (int16)sh.group;
        if (sh.kind == BENCH_SHAPE_CIRCLE) {
            b2CircleShape c;
            c.m_p.Set((float)sh.x1, (float)sh.y1);
            c.m_radius = (float)sh.radius;
            fd.shape = &c;
            body->CreateFixture(&fd);
            double mc = sh.density * kPi * sh.radius * sh.radius;
            m->mass += mc;
            m->mx += mc * sh.x1;
            m->my += mc * sh.y1;
            m->inertia += mc * (0.5 * sh.radius * sh.radius + sh.x1 * sh.x1 + sh.y1 * sh.y1);
            return false;
        }
        if (sh.kind == BENCH_SHAPE_CAPSULE) {
            double cx = 0.5 * (sh.x1 + sh.x2), cy = 0.5 * (sh.y1 + sh.y2);
            double L = std::hypot(sh.x2 - sh.x1, sh.y2 - sh.y1), angle = std::atan2(sh.y2 - sh.y1, sh.x2 - sh.x1);
            b2PolygonShape box;
            box.SetAsBox((float)(0.5 * L), (float)sh.radius, b2Vec2((float)cx, (float)cy), (float)angle);
            fd.shape = &box;
            body->CreateFixture(&fd);
            fd.density = (float)(0.5 * sh.density);
            for (int e = 0; e < 2; ++e) {
                b2CircleShape c;
                c.m_p.Set((float)(e ? sh.x2 : sh.x1), (float)(e ? sh.y2 : sh.y1));
                c.m_radius = (float)sh.radius;
                fd.shape = &c;
                body->CreateFixture(&fd);
            }
            double mc, ic;
            capsule_mass(sh, &mc, &ic);
            m->mass += mc;
            m->mx += mc * cx;
            m->my += mc * cy;
            m->inertia += ic + mc * (cx * cx + cy * cy);
            return true;
        }
        b2Vec2 v[b2_maxPolygonVertices];
        int n = sh.count < b2_maxPolygonVertices ? sh.count : b2_maxPolygonVertices;
        if (sh.radius > 0)
            inflate_polygon(sh, v);
        else
            for (int k = 0; k < n; ++k) v[k].Set((float)sh.px[k], (float)sh.py[k]);
        b2PolygonShape poly;
        poly.Set(v, n);
        fd.shape = &poly;
        body->CreateFixture(&fd);
        b2MassData md;
        poly.ComputeMass(&md, fd.density);
        m->mass += md.mass;
        m->mx += md.mass * md.center.x;
        m->my += md.mass * md.center.y;
        m->inertia += md.I;
        return false;
    }

    b2World world_; /* owns the bodies and joints */
    std::vector<b2Body *> bodies_;
    bool ok_;
};

class ChipmunkWorld : public World {
public:
    explicit ChipmunkWorld(const bench_scene &s) : space_(cpSpaceNew()), ok_(chipmunk_builds(s))
    {
        cpSpaceSetIterations(space_, kChipmunkIterations);
        cpSpaceSetGravity(space_, cpv(s.gx, s.gy));
        cpSpaceSetCollisionSlop(space_, kChipmunkSlop);
        /* sleeping must be on before any body can be put to sleep */
        if (s.sleep) cpSpaceSetSleepTimeThreshold(space_, kChipmunkSleepTime);
        bodies_.reserve((size_t)s.count);
        shapes_.reserve((size_t)s.count);
        for (int i = 0; i < s.count; ++i) {
            const bench_body &b = s.bodies[i];
            const bench_shape *c = lone_circle(s, b);
            cpBody *body;
            ok_ = ok_ && (b.shape_count == 0 || c); /* chipmunk_builds said so */
            if (b.type == BENCH_DYNAMIC && c) {
                double m = c->density * kPi * c->radius * c->radius;
                body = cpBodyNew(m, cpMomentForCircle(m, 0, c->radius, cpvzero));
            } else if (b.type == BENCH_DYNAMIC) {
                double m = b.density * 4 * b.hx * b.hy;
                body = cpBodyNew(m, cpMomentForBox(m, 2 * b.hx, 2 * b.hy));
            } else {
                body = b.type == BENCH_KINEMATIC ? cpBodyNewKinematic() : cpBodyNewStatic();
            }
            /* placed before its shape is added, so no reindexing is needed */
            cpBodySetPosition(body, cpv(b.x, b.y));
            if (b.type != BENCH_STATIC) {
                cpBodySetVelocity(body, cpv(b.vx, b.vy));
                cpBodySetAngularVelocity(body, b.w);
            }
            cpSpaceAddBody(space_, body);
            cpShape *shape = c ? cpCircleShapeNew(body, c->radius, cpvzero) : cpBoxShapeNew(body, 2 * b.hx, 2 * b.hy, 0);
            /* Chipmunk multiplies the two shapes' friction: sqrt on each gives
               sqrt(mu_a mu_b), the other engines' rule */
            cpShapeSetFriction(shape, std::sqrt(c ? c->friction : b.friction));
            if (c) cpShapeSetFilter(shape, cpShapeFilterNew(CP_NO_GROUP, c->category, c->mask));
            cpShapeSetElasticity(shape, 0);
            cpSpaceAddShape(space_, shape);
            bodies_.push_back(body);
            shapes_.push_back(shape);
        }
        /* only a body in a space can sleep; each sleeps as its own island */
        for (int i = 0; i < s.count; ++i)
            if (s.bodies[i].asleep && s.bodies[i].type == BENCH_DYNAMIC) cpBodySleep(bodies_[(size_t)i]);
        joints_.reserve((size_t)s.joint_count);
        for (int i = 0; i < s.joint_count; ++i) {
            const bench_joint &j = s.joints[i];
            /* a pin at the two anchors: no limit, no motor, infinite max force; the
               two bodies' shapes stop colliding (cpConstraintSetCollideBodies) */
            cpConstraint *pin =
                cpPivotJointNew2(bodies_[(size_t)j.a], bodies_[(size_t)j.b], cpv(j.ax, j.ay), cpv(j.bx, j.by));
            cpConstraintSetCollideBodies(pin, cpFalse);
            cpSpaceAddConstraint(space_, pin);
            joints_.push_back(pin);
        }
    }
    ~ChipmunkWorld()
    {
        /* the space reads its bodies while it is freed, so it goes first */
        cpSpaceFree(space_);
        for (size_t i = 0; i < joints_.size(); ++i) cpConstraintFree(joints_[i]);
        for (size_t i = 0; i < shapes_.size(); ++i) cpShapeFree(shapes_[i]);
        for (size_t i = 0; i < bodies_.size(); ++i) cpBodyFree(bodies_[i]);
    }
    bool ok() const { return space_ != NULL && ok_; }
    bool step(double dt)
    {
        cpSpaceStep(space_, dt);
        return true;
    }
    void pose(int i, double *x, double *y, double *angle) const
    {
        cpVect p = cpBodyGetPosition(bodies_[(size_t)i]);
        *x = p.x;
        *y = p.y;
        *angle = cpBodyGetAngle(bodies_[(size_t)i]);
    }
    void velocity(int i, double *vx, double *vy) const
    {
        cpVect v = cpBodyGetVelocity(bodies_[(size_t)i]);
        *vx = v.x;
        *vy = v.y;
    }
    void set_velocity(int i, double vx, double vy, double w)
    {
        cpBodySetVelocity(bodies_[(size_t)i], cpv(vx, vy));
        cpBodySetAngularVelocity(bodies_[(size_t)i], w);
    }
    bool awake(int i) const { return !cpBodyIsSleeping(bodies_[(size_t)i]); }

private:
    ChipmunkWorld(const ChipmunkWorld &);
    ChipmunkWorld &operator=(const ChipmunkWorld &);
    cpSpace *space_;
    std::vector<cpBody *> bodies_;
    std::vector<cpShape *> shapes_;
    std::vector<cpConstraint *> joints_;
    bool ok_;
};

template <class W> static World *build(const bench_scene &s) { return new W(s); }
static World *build_ga2d(const bench_scene &s) { return new CWorld<ga2d_peer>(s, kGa2dGeneric); }
#if PEERS_AVX2
static World *build_ga2d_avx2(const bench_scene &s) { return new CWorld<ga2d_peer>(s, kGa2dAvx2); }
#endif
#if PEERS_B2V3
static World *build_b2v3(const bench_scene &s) { return new CWorld<b2v3_peer>(s, kB2v3); }
#endif
/* The same engines on 2 workers: ga2d on examples/task_pool.h's pool, Box2D
   v3 on its own scheduler (the worlds made here only) */
static World *build_ga2d_2w(const bench_scene &s)
{
    ga2d_peer_use_workers(2);
    World *w = new CWorld<ga2d_peer>(s, kGa2dGeneric);
    ga2d_peer_use_workers(1);
    return w;
}
#if PEERS_B2V3
static World *build_b2v3_2w(const bench_scene &s)
{
    b2v3_peer_use_workers(2);
    World *w = new CWorld<b2v3_peer>(s, kB2v3);
    b2v3_peer_use_workers(1);
    return w;
}
#endif

static bool builds_all(const bench_scene &) { return true; }

struct Engine {
    const char *name;
    World *(*build)(const bench_scene &s);
    bool (*builds)(const bench_scene &s); /* false: the engine sits the scene out */
};

/* ga2d first (its median is every ratio's numerator); Box2D v3 where
   B2V3_SRC gave its sources; ga2d on 2 workers, and Box2D v3 on 2 where
   it is built (each engine's own speed-up from a second core, measured in
   the same run); ga2d's AVX2 build, where there is one, last, with its own
   ratios */
static const Engine kEngines[] = {{"ga2d", build_ga2d, builds_all},
                                  {"Box2D", build<Box2dWorld>, builds_all},
                                  {"Chipmunk", build<ChipmunkWorld>, chipmunk_builds},
#if PEERS_B2V3
                                  {"Box2D-v3", build_b2v3, builds_all},
#endif
                                  {"ga2d-2w", build_ga2d_2w, builds_all},
#if PEERS_B2V3
                                  {"Box2D-v3-2w", build_b2v3_2w, builds_all},
#endif
#if PEERS_AVX2
                                  {"ga2d-avx2", build_ga2d_avx2, builds_all}
#endif
};
static const int kEngineCount = (int)(sizeof kEngines / sizeof kEngines[0]);
static const int kAvx2 = PEERS_AVX2 ? kEngineCount - 1 : -1; /* ga2d-avx2's index, -1 when not built */
static const int kBox2d = 1;                                  /* Box2D 2.4.1's index */
static const int kV3 = PEERS_B2V3 ? 3 : -1;                   /* Box2D v3's index, -1 when not built */
static const int kGa2d2w = PEERS_B2V3 ? 4 : 3;                /* ga2d on 2 workers */
static const int kV32w = PEERS_B2V3 ? 5 : -1;                 /* Box2D v3 on 2 workers, -1 when not built */
static bool g_engine_on[kEngineCount];                        /* PEERS_ENGINES: the engines to run */

/* ------------------------------------------------------- accuracy figures */
/* The scene's boxes (their nominal size, no engine's skin) placed by an
   engine's poses: the same geometry measured the same way for all. */
struct PlacedBox {
    double x, y, c, s, hx, hy;
    double lo_x, hi_x, lo_y, hi_y;
    int dynamic;
};

static void place_boxes(const bench_scene &s, const World &w, std::vector<PlacedBox> &out)
{
    out.resize((size_t)s.count);
    for (int i = 0; i < s.count; ++i) {
        PlacedBox &b = out[(size_t)i];
        double angle;
        w.pose(i, &b.x, &b.y, &angle);
        b.c = std::cos(angle);
        b.s = std::sin(angle);
        b.hx = s.bodies[i].hx;
        b.hy = s.bodies[i].hy;
        double ex = b.hx * std::fabs(b.c) + b.hy * std::fabs(b.s);
        double ey = b.hx * std::fabs(b.s) + b.hy * std::fabs(b.c);
        b.lo_x = b.x - ex;
        b.hi_x = b.x + ex;
        b.lo_y = b.y - ey;
        b.hi_y = b.y + ey;
        b.dynamic = s.bodies[i].type == BENCH_DYNAMIC;
    }
}

/* Penetration depth of two boxes by the separating-axis test: the least
   overlap over the four face normals; 0 when some axis separates them. */
static double box_overlap(const PlacedBox &a, const PlacedBox &b)
{
    const double axes[4][2] = {{a.c, a.s}, {-a.s, a.c}, {b.c, b.s}, {-b.s, b.c}};
    double dx = b.x - a.x, dy = b.y - a.y, depth = 1e300;
    for (int k = 0; k < 4; ++k) {
        double nx = axes[k][0], ny = axes[k][1];
        double ra = a.hx * std::fabs(a.c * nx + a.s * ny) + a.hy * std::fabs(-a.s * nx + a.c * ny);
        double rb = b.hx * std::fabs(b.c * nx + b.s * ny) + b.hy * std::fabs(-b.s * nx + b.c * ny);
        double o = ra + rb - std::fabs(dx * nx + dy * ny);
        if (o <= 0) return 0;
        depth = std::min(depth, o);
    }
    return depth;
}

struct ByLowX {
    const std::vector<PlacedBox> *boxes;
    bool operator()(int a, int b) const { return (*boxes)[(size_t)a].lo_x < (*boxes)[(size_t)b].lo_x; }
};

/* The deepest overlap between any two boxes, one of them dynamic (the
   pairs an engine collides), found by sweep and prune along x. */
static double deepest_overlap(const std::vector<PlacedBox> &boxes, std::vector<int> &order)
{
    order.resize(boxes.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = (int)i;
    ByLowX by = {&boxes};
    std::sort(order.begin(), order.end(), by);
    double deepest = 0;
    for (size_t i = 0; i < order.size(); ++i) {
        const PlacedBox &a = boxes[(size_t)order[i]];
        for (size_t j = i + 1; j < order.size(); ++j) {
            const PlacedBox &b = boxes[(size_t)order[j]];
            if (b.lo_x > a.hi_x) break;
            if (!(a.dynamic || b.dynamic) || b.lo_y > a.hi_y || a.lo_y > b.hi_y) continue;
            deepest = std::max(deepest, box_overlap(a, b));
        }
    }
    return deepest;
}

/* |sum m v - P0| / |P0| with m = density x area from the scene, the
   same masses for every engine. */
static double momentum_error(const bench_scene &s, const World &w)
{
    double p0x = 0, p0y = 0, px = 0, py = 0;
    for (int i = 0; i < s.count; ++i) {
        const bench_body &b = s.bodies[i];
        if (b.type != BENCH_DYNAMIC) continue;
        double m = b.density * 4 * b.hx * b.hy, vx, vy;
        w.velocity(i, &vx, &vy);
        p0x += m * b.vx;
        p0y += m * b.vy;
        px += m * vx;
        py += m * vy;
    }
    return std::hypot(px - p0x, py - p0y) / std::hypot(p0x, p0y);
}

static double moved(const bench_scene &s, const World &w, int i)
{
    double x, y, angle;
    w.pose(i, &x, &y, &angle);
    return std::hypot(x - s.bodies[i].x, y - s.bodies[i].y);
}

/* dynamic bodies, but `skip`, that moved farther than `beyond` */
static int count_moved(const bench_scene &s, const World &w, double beyond, int skip)
{
    int n = 0;
    for (int i = 0; i < s.count; ++i)
        if (s.bodies[i].type == BENCH_DYNAMIC && i != skip && moved(s, w, i) > beyond) ++n;
    return n;
}


/* dynamic boxes turned more than `degrees` from their start (all start
   square to the axes): a box that fell over, not one that sank */
static int count_tilted(const bench_scene &s, const World &w, double degrees)
{
    int n = 0;
    for (int i = 0; i < s.count; ++i) {
        if (s.bodies[i].type != BENCH_DYNAMIC) continue;
        double x, y, angle;
        w.pose(i, &x, &y, &angle);
        if (std::fabs(std::remainder(angle, 2 * kPi)) > degrees * kPi / 180) ++n;
    }
    return n;
}

/* ------------------------------------------------------ library warnings */
/* Debian's Chipmunk keeps its debug checks and prints warnings (such as
   "High EPA iterations") on stderr while it steps.  A run's stderr goes to
   a temporary file and is summed up in the check column, so the tables
   stay readable; anything else caught is passed on.  Should a run abort,
   the signal handler hands the caught text back first. */
static int g_saved_stderr = -1, g_caught_fd = -1;

static void give_back_stderr(int sig)
{
    if (g_saved_stderr >= 0) {
        char buf[4096];
        ssize_t n;
        dup2(g_saved_stderr, 2);
        lseek(g_caught_fd, 0, SEEK_SET);
        while ((n = read(g_caught_fd, buf, sizeof buf)) > 0)
            if (write(2, buf, (size_t)n) < 0) break;
    }
    signal(sig, SIG_DFL);
    raise(sig);
}

class StderrCatcher {
public:
    StderrCatcher() : file_(tmpfile())
    {
        if (!file_) return;
        fflush(stderr);
        g_caught_fd = fileno(file_);
        g_saved_stderr = dup(2);
        dup2(g_caught_fd, 2);
        signal(SIGABRT, give_back_stderr);
        signal(SIGSEGV, give_back_stderr);
    }
    /* Ends the catch; returns a summary of the library's warnings ("" when
       none) and passes any other caught line on to stderr. */
    std::string finish()
    {
        if (!file_) return "";
        fflush(stderr);
        dup2(g_saved_stderr, 2);
        close(g_saved_stderr);
        g_saved_stderr = -1;
        signal(SIGABRT, SIG_DFL);
        signal(SIGSEGV, SIG_DFL);
        rewind(file_);
        char line[512], first[512] = "";
        int warnings = 0;
        bool in_warning = false;
        const char *tag = "Chipmunk warning: ";
        while (fgets(line, sizeof line, file_)) {
            if (strncmp(line, tag, strlen(tag)) == 0) {
                if (!warnings++) snprintf(first, sizeof first, "%s", line + strlen(tag));
                in_warning = true;
            } else if (!(in_warning && line[0] == '\t')) { /* a warning's own detail lines start with a tab */
                in_warning = false;
                fputs(line, stderr);
            }
        }
        fclose(file_);
        file_ = NULL;
        if (!warnings) return "";
        first[strcspn(first, "\n")] = 0;
        char summary[600];
        snprintf(summary, sizeof summary, "; Chipmunk warned %d times (\"%s\")", warnings, first);
        return summary;
    }
    ~StderrCatcher() { finish(); }

private:
    StderrCatcher(const StderrCatcher &);
    StderrCatcher &operator=(const StderrCatcher &);
    FILE *file_;
};

/* ------------------------------------------------------------------ runs */
struct RunResult {
    double ms;          /* per timed step */
    double figure;      /* the scene's accuracy figure */
    std::string check;  /* what says the scene behaved (see scene_check) */
    std::string failed; /* non-empty when the run could not finish */
    int blown_up;       /* a scene with joints: the step after which a body passed kBlownUpSpeed, else -1 */
    int stopped;        /* the step after which the run passed g_max_run_ms of stepping, else -1 */
};

/* The fastest dynamic body's speed, m/s. */
static double fastest(const bench_scene &s, const World &w)
{
    double top = 0;
    for (int i = 0; i < s.count; ++i) {
        if (s.bodies[i].type != BENCH_DYNAMIC) continue;
        double vx, vy;
        w.velocity(i, &vx, &vy);
        double v = std::hypot(vx, vy);
        if (!(v <= top)) top = v; /* a NaN sticks */
    }
    return top;
}

struct RunStats {
    int asleep_wanted, asleep_at_start; /* bodies the scene creates asleep; of them, asleep after building */
    int deep_steps;                     /* steps whose deepest overlap passed kDeepOverlap */
    double turn;                        /* BENCH_FIG_LAG: the probe's turn over the run, rad */
};

/* The worst joint separation at the end (bench_scene_joint_gap), m. */
static double joint_gap(const bench_scene &s, const World &w)
{
    std::vector<double> x((size_t)s.count), y((size_t)s.count), angle((size_t)s.count);
    for (int i = 0; i < s.count; ++i) w.pose(i, &x[(size_t)i], &y[(size_t)i], &angle[(size_t)i]);
    return s.count ? bench_scene_joint_gap(&s, &x[0], &y[0], &angle[0]) : 0;
}

/* A plain-words check that the engine ran the scene as meant: pyramids
   stand, the striker ploughs through, the tumbler's boxes tumble and stay
   inside, the joint grid hangs together. */
static std::string scene_check(const bench_scene &s, const World &w, const RunStats &st)
{
    char line[256];
    if (s.figure == BENCH_FIG_SAG) {
        double x, y, angle, lowest = 1e300;
        w.pose(s.probe, &x, &y, &angle);
        for (int i = 0; i < s.count; ++i) {
            double xi, yi, ai;
            w.pose(i, &xi, &yi, &ai);
            lowest = std::min(lowest, yi);
        }
        snprintf(line, sizeof line, "corner dx %+.3f dy %+.3f m; lowest body at y %.3f m; worst joint separation %.4f m",
                 x - s.bodies[s.probe].x, y - s.bodies[s.probe].y, lowest, joint_gap(s, w));
    } else if (s.figure == BENCH_FIG_LAG) {
        /* a body is out when its centre is beyond the loop's radius from
           the loop's centre, the mean of its points */
        double cx = 0, cy = 0, r2 = 0;
        int out = 0;
        for (int k = 0; k < s.chain_count; ++k) {
            cx += s.chain_x[k] / s.chain_count;
            cy += s.chain_y[k] / s.chain_count;
        }
        for (int k = 0; k < s.chain_count; ++k) r2 = std::max(r2, std::hypot(s.chain_x[k] - cx, s.chain_y[k] - cy));
        for (int i = 0; i < s.count; ++i) {
            double x, y, a;
            if (s.bodies[i].type != BENCH_DYNAMIC) continue;
            w.pose(i, &x, &y, &a);
            out += !(std::hypot(x - cx, y - cy) <= r2);
        }
        snprintf(line, sizeof line, "bar turned %.2f rad (its motor: %.2f rad); bodies out of the loop: %d", st.turn,
                 s.joints[0].motor_speed * s.steps * s.dt, out);
    } else if (s.figure == BENCH_FIG_DRIFT) {
        double x, y, angle;
        w.pose(s.probe, &x, &y, &angle);
        snprintf(line, sizeof line, "top dx %+.3f dy %+.3f m; boxes moved > 0.5 m: %d, tilted > 10 deg: %d",
                 x - s.bodies[s.probe].x, y - s.bodies[s.probe].y, count_moved(s, w, 0.5, s.probe), count_tilted(s, w, 10));
    } else if (s.figure == BENCH_FIG_MOMENTUM) {
        double x, y, angle, vx, vy;
        w.pose(s.probe, &x, &y, &angle);
        w.velocity(s.probe, &vx, &vy);
        snprintf(line, sizeof line, "striker x %.1f m, vx %.1f m/s; squares moved > 0.1 m: %d; asleep at start: %d/%d",
                 x, vx, count_moved(s, w, 0.1, s.probe), st.asleep_at_start, st.asleep_wanted);
    } else {
        /* a box is out when it is past a wall's midline in the tumbler's
           own frame (wall 0 gives the frame's angle) */
        double wx, wy, turn;
        int out = 0, dynamic = 0;
        w.pose(0, &wx, &wy, &turn);
        double c = std::cos(turn), sn = std::sin(turn);
        for (int i = 0; i < s.count; ++i) {
            if (s.bodies[i].type != BENCH_DYNAMIC) continue;
            double x, y, angle;
            w.pose(i, &x, &y, &angle);
            double dx = x - s.pivot_x, dy = y - s.pivot_y;
            double lx = c * dx + sn * dy, ly = -sn * dx + c * dy;
            if (std::fabs(lx) > 10 || std::fabs(ly) > 10) ++out;
            ++dynamic;
        }
        double turned = std::fmod(turn * 180 / kPi, 360); /* engines wrap angles differently */
        if (turned < 0) turned += 360;
        /* wall 0 starts 10 m from the pivot and stays there if the turn
           is rigid */
        snprintf(line, sizeof line,
                 "turned %.0f deg, wall 0 at %.2f m from the pivot; out of the tumbler: %d; moved > 1 m: %d/%d; "
                 "steps with an overlap > %g m: %d",
                 turned, std::hypot(wx - s.pivot_x, wy - s.pivot_y), out, count_moved(s, w, 1.0, -1), dynamic,
                 kDeepOverlap, st.deep_steps);
    }
    return line;
}

static RunResult run_once(const Engine &e, const bench_scene &s)
{
    RunResult r;
    r.ms = 0;
    r.figure = 0;
    r.blown_up = -1;
    r.stopped = -1;
    double stepping = 0; /* every step's time, the untimed first ones too */
    StderrCatcher caught;
    World *w = e.build(s);
    if (!w->ok()) {
        r.failed = "could not build the world";
        delete w;
        return r;
    }
    RunStats st = {0, 0, 0, 0};
    for (int i = 0; i < s.count; ++i)
        if (s.bodies[i].asleep) {
            ++st.asleep_wanted;
            st.asleep_at_start += !w->awake(i);
        }
    std::vector<PlacedBox> boxes;
    std::vector<int> order;
    double total = 0, deepest = 0, probe_angle = 0;
    if (s.figure == BENCH_FIG_LAG) {
        double x, y;
        w->pose(s.probe, &x, &y, &probe_angle);
    }
    for (int step = 0; step < s.steps; ++step) {
        /* kinematic walls turn rigidly: each takes the velocity of the
           turning frame at its current centre */
        for (int i = 0; i < s.count; ++i) {
            if (s.bodies[i].type != BENCH_KINEMATIC) continue;
            double x, y, angle, vx, vy;
            w->pose(i, &x, &y, &angle);
            bench_scene_kinematic_velocity(&s, x, y, &vx, &vy);
            w->set_velocity(i, vx, vy, s.pivot_w);
        }
        double t0 = now_ms();
        bool stepped = w->step(s.dt);
        double t1 = now_ms();
        if (!stepped) {
            r.failed = "the step failed";
            break;
        }
        if (step >= kUntimedSteps) total += t1 - t0;
        if (s.joint_count > 0 && !(fastest(s, *w) <= kBlownUpSpeed)) {
            r.blown_up = step;
            break;
        }
        stepping += t1 - t0;
        if (stepping > g_max_run_ms && step + 1 < s.steps) {
            r.stopped = step;
            break;
        }
        if (s.figure == BENCH_FIG_PENETRATION) {
            place_boxes(s, *w, boxes);
            double d = deepest_overlap(boxes, order);
            deepest = std::max(deepest, d);
            st.deep_steps += d > kDeepOverlap;
        }
        if (s.figure == BENCH_FIG_LAG) {
            double x, y, now;
            w->pose(s.probe, &x, &y, &now);
            st.turn += bench_scene_turn(probe_angle, now);
            probe_angle = now;
        }
    }
    if (r.blown_up >= 0 || r.stopped >= 0) {
        char line[200];
        if (r.blown_up >= 0)
            snprintf(line, sizeof line, "blew up after step %d of %d: a body faster than %g m/s; no time, no figure",
                     r.blown_up + 1, s.steps, kBlownUpSpeed);
        else
            snprintf(line, sizeof line,
                     "stopped after step %d of %d: %.1f s of stepping (PEERS_MAX_RUN_S), %.3g ms/step; no figure",
                     r.stopped + 1, s.steps, stepping / 1e3, stepping / (r.stopped + 1));
        r.blown_up = 0; /* one way or the other, the engine's run ended early */
        r.check = line;
        delete w;
        r.check += caught.finish();
        return r;
    }
    r.ms = total / (s.steps - kUntimedSteps);
    if (s.figure == BENCH_FIG_DRIFT) {
        r.figure = moved(s, *w, s.probe);
    } else if (s.figure == BENCH_FIG_SAG) {
        double x, y, angle;
        w->pose(s.probe, &x, &y, &angle);
        r.figure = s.bodies[s.probe].y - y;
    }
    else if (s.figure == BENCH_FIG_MOMENTUM)
        r.figure = momentum_error(s, *w);
    else if (s.figure == BENCH_FIG_LAG)
        r.figure = bench_scene_lag(&s, st.turn);
    else
        r.figure = deepest;
    r.check = scene_check(s, *w, st);
    delete w;
    r.check += caught.finish();
    return r;
}

static double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

static double minimum(const std::vector<double> &v) { return *std::min_element(v.begin(), v.end()); }

/* ------------------------------------------------------------------ main */
static const char *const kScenes[] = {"large_pyramid", "many_pyramids", "smash",      "tumbler", "pyramid20",
                                     "stack10",       "mixed_bin",     "joint_grid", "spinner"};
static const int kSceneCount = (int)(sizeof kScenes / sizeof kScenes[0]);

static const char *cxx_compiler()
{
#if defined(__clang__)
    return "clang++ " __clang_version__;
#elif defined(__GNUC__)
    return "g++ " __VERSION__;
#else
    return "unknown C++ compiler";
#endif
}

static void print_header(int runs)
{
    char b2[64];
    snprintf(b2, sizeof b2, "%d.%d.%d", b2_version.major, b2_version.minor, b2_version.revision);
    if (*PEERS_BOX2D_VERSION && strcmp(b2, PEERS_BOX2D_VERSION) != 0)
        snprintf(b2, sizeof b2, "%s (b2_version says %d.%d.%d)", PEERS_BOX2D_VERSION, b2_version.major,
                 b2_version.minor, b2_version.revision);
    printf("bench-peers: ga2d vs Box2D %s vs Chipmunk %s%s\n", b2, cpVersionString, PEERS_B2V3 ? " vs Box2D v3" : "");
    printf("  %d runs per engine and scene, engines alternating; dt = 1/60; ms/step = world step time over\n"
           "  the steps after the first %d (building, wall velocities and figures untimed)\n",
           runs, kUntimedSteps);
    printf("compilers: driver %s (C++, %s); ga2d %s (C99, same flags), ga2d_real = %s;\n"
           "  Box2D and Chipmunk: the system's shared libraries (-lbox2d, -lchipmunk)\n",
           cxx_compiler(), PEERS_OPT, ga2d_peer_compiler(), ga2d_peer_real_is_double() ? "double" : "float");
    if (PEERS_AVX2)
        printf("  ga2d-avx2: the same ga2d built again with -mavx2 (8 float lanes; the same results bit for bit),\n"
               "  the CPU having AVX2; the peers' libraries are the distribution's generic builds\n");
    printf("settings (all: box polygons, or circles with their filter bits, density and friction from the scene,\n"
           "  restitution 0, sleep per scene; the scene's joints revolute, at the defaults):\n");
    printf("  ga2d      %s; sleep: bodies created with is_awake = 0\n", ga2d_peer_settings());
    printf("  Box2D     %d velocity + %d position iterations; SetAsBox (polygon skin %.3f m, linear slop %.3f m);\n"
           "            friction mixes as sqrt; continuous collision on (default; off on spinner, where its\n"
           "            SolveTOI stalls); sleep: bd.awake = false\n",
           kBox2dVelocityIterations, kBox2dPositionIterations, (double)b2_polygonRadius, (double)b2_linearSlop);
    printf("            joints: b2RevoluteJoint (solved with the same iterations)\n");
    printf("  Chipmunk  %d iterations; cpBoxShapeNew radius 0; collision slop %.3f m; mass = density x area,\n"
           "            cpMomentForBox; shape friction sqrt(mu) (pairs multiply); sleep time %.1f s, bodies\n"
           "            put to sleep with cpBodySleep after they are added; cpFloat = %s; the library is\n"
           "            built with its debug checks (see its banner above); its warnings are counted per run\n",
           kChipmunkIterations, kChipmunkSlop, kChipmunkSleepTime, sizeof(cpFloat) == sizeof(double) ? "double" : "float");
    printf("            joints: cpPivotJointNew2 at the two anchors (default error bias, max force infinite);\n"
           "            scenes with other shapes, a chain or a motor (spinner): left out\n");
    printf("  Box2D (2.4.1) capsules: a box and two half-density circles, mass and inertia set to the capsule's;\n"
           "            rounded polygons: the sharp polygon around the rounding; a chain loop: a static body per\n"
           "            one-sided edge, the neighbours as ghosts (on one body AddPair makes a run take minutes)\n");
#if PEERS_B2V3
    printf("  Box2D-v3  %s;\n"
           "            built from %s with %s %s\n"
           "            (-I its include and src); shapes, chains and joints through its public API\n",
           b2v3_peer_settings(), PEERS_B2V3_SRC, b2v3_peer_compiler(), PEERS_B2V3_CFLAGS);
#endif
    printf("  ga2d-2w, Box2D-v3-2w: the same engines on 2 workers (ga2d: examples/task_pool.h's pool; Box2D v3:\n"
           "            its built-in scheduler), each engine's speed-up from a second core in the same run\n");
    printf("figures, measured alike in every engine from its poses and velocities:\n"
           "  drift: the top box's distance from its start at the end (m); Box2D's boxes rest on their skins,\n"
           "    so its stacks stand about 0.013 m per layer higher than they were built\n"
           "  momentum: |sum m v - P0| / |P0| at the end, m = density x area from the scene\n"
           "  penetration: the deepest overlap, over every step, of two of the scene's boxes at their\n"
           "    nominal size (Box2D's 0.01 m skin is not part of the box), one of them dynamic (m)\n"
           "  sag: how far the joint grid's bottom corner ends below its start (m); the check gives the\n"
           "    worst joint separation at the end: the largest distance between a joint's two anchors\n"
           "  lag: how far spinner's bar's turn over the run falls short of its motor's speed x time (rad)\n"
           "ratio = ga2d median / peer median: below 1, ga2d is faster\n");
}

int main(int argc, char **argv)
{
    int runs = 3;
    const char *env = getenv("BENCH_RUNS");
    if (env && *env) {
        char *end;
        long n = strtol(env, &end, 10);
        if (*end || n < 1 || n > 1000) {
            fprintf(stderr, "peers: BENCH_RUNS must be a whole number from 1 to 1000, not '%s'\n", env);
            return 2;
        }
        runs = (int)n;
    }
    const char *max_run = getenv("PEERS_MAX_RUN_S");
    if (max_run && *max_run) {
        char *end;
        double sec = strtod(max_run, &end);
        if (*end || !(sec > 0)) {
            fprintf(stderr, "peers: PEERS_MAX_RUN_S must be a positive number of seconds, not '%s'\n", max_run);
            return 2;
        }
        g_max_run_ms = sec * 1e3;
    }
    /* the engines asked for: all, or PEERS_ENGINES's names separated by commas */
    const char *engines = getenv("PEERS_ENGINES");
    for (int e = 0; e < kEngineCount; ++e) g_engine_on[e] = !engines || !*engines;
    for (const char *name = engines; name && *name;) {
        size_t n = strcspn(name, ",");
        bool known = false;
        for (int e = 0; e < kEngineCount; ++e)
            if (strlen(kEngines[e].name) == n && strncmp(name, kEngines[e].name, n) == 0) known = g_engine_on[e] = true;
        if (!known) {
            fprintf(stderr, "peers: unknown engine '%.*s' in PEERS_ENGINES; engines:", (int)n, name);
            for (int e = 0; e < kEngineCount; ++e) fprintf(stderr, " %s", kEngines[e].name);
            fprintf(stderr, "\n");
            return 2;
        }
        name += n + (name[n] == ',');
    }
    /* the scenes asked for: "all", or names separated by commas */
    bool wanted[kSceneCount];
    const char *asked = argc > 1 ? argv[1] : "all";
    for (int k = 0; k < kSceneCount; ++k) wanted[k] = strcmp(asked, "all") == 0;
    for (const char *name = asked; strcmp(asked, "all") != 0 && *name;) {
        size_t n = strcspn(name, ",");
        bool known = false;
        for (int k = 0; k < kSceneCount; ++k)
            if (strlen(kScenes[k]) == n && strncmp(name, kScenes[k], n) == 0) known = wanted[k] = true;
        if (!known) {
            fprintf(stderr, "peers: unknown scene '%.*s'; scenes:", (int)n, name);
            for (int k = 0; k < kSceneCount; ++k) fprintf(stderr, " %s", kScenes[k]);
            fprintf(stderr, " (or all; several: a,b)\n");
            return 2;
        }
        name += n + (name[n] == ',');
    }
    const char *csv_path = argc > 2 ? argv[2] : "build/bench/peers.csv";
    FILE *csv = fopen(csv_path, "w");
    if (!csv) fprintf(stderr, "peers: cannot write %s; no CSV this time\n", csv_path);
    if (csv) fprintf(csv, "scene,engine,ms_median,ms_min,figure_name,figure,ratio,ratio_avx2,over_v3\n");

    /* Chipmunk greets on its first space; let that happen before the tables */
    cpSpaceFree(cpSpaceNew());
    print_header(runs);
    if (runs < 3) printf("note: fewer than 3 runs, so the medians are not robust\n");
    double t_start = now_ms();
    int failures = 0;
    for (int k = 0; k < kSceneCount; ++k) {
        if (!wanted[k]) continue;
        bench_scene s;
        if (bench_scene_make(kScenes[k], &s) != 0) {
            fprintf(stderr, "peers: cannot make scene %s\n", kScenes[k]);
            return 1;
        }
        printf("\n%s: %d bodies, %d steps, sleep %s; figure: %s\n", s.name, s.count, s.steps, s.sleep ? "on" : "off",
               bench_scene_figure_name(&s));
        fflush(stdout);
        std::vector<double> ms[kEngineCount], fig[kEngineCount];
        std::string check[kEngineCount], failed[kEngineCount], blown[kEngineCount];
        bool left_out[kEngineCount];
        for (int e = 0; e < kEngineCount; ++e) left_out[e] = !kEngines[e].builds(s) || !g_engine_on[e];
        for (int r = 0; r < runs; ++r)
            for (int e = 0; e < kEngineCount; ++e) {
                if (left_out[e] || !failed[e].empty() || !blown[e].empty()) continue;
                RunResult res = run_once(kEngines[e], s);
                if (!res.failed.empty()) {
                    failed[e] = res.failed;
                    continue;
                }
                if (res.blown_up >= 0) { /* the engine's result, not the runner's failure: once is enough */
                    blown[e] = res.check;
                    continue;
                }
                ms[e].push_back(res.ms);
                fig[e].push_back(res.figure);
                check[e] = res.check;
            }
        printf("  %-14s %-11s %12s %8s %10s %12s%s\n", "scene", "engine", "ms/step med", "min", "ga2d/peer", "figure",
               kAvx2 >= 0 ? "  ga2d-avx2/peer" : "");
        double ga2d_med = ms[0].empty() ? NAN : median(ms[0]);
        double avx2_med = kAvx2 < 0 || ms[kAvx2].empty() ? NAN : median(ms[kAvx2]);
        double v3_med = kV3 < 0 || ms[kV3].empty() ? NAN : median(ms[kV3]);
        std::string notes;
        for (int e = 0; e < kEngineCount; ++e) {
            if (left_out[e]) {
                printf("  %-14s %-11s left out: %s\n", s.name, kEngines[e].name,
                       g_engine_on[e] ? "the runner builds it boxes and centred circles with pins only" : "not in PEERS_ENGINES");
                if (csv)
                    fprintf(csv, "%s,%s,nan,nan,\"%s\",nan,nan,nan,nan\n", s.name, kEngines[e].name,
                            bench_scene_figure_name(&s));
                continue;
            }
            if (!failed[e].empty()) {
                printf("  %-14s %-11s FAILED: %s\n", s.name, kEngines[e].name, failed[e].c_str());
                ++failures;
                continue;
            }
            if (!blown[e].empty()) {
                printf("  %-14s %-11s %s\n", s.name, kEngines[e].name, blown[e].c_str());
                if (csv)
                    fprintf(csv, "%s,%s,nan,nan,\"%s\",nan,nan,nan,nan\n", s.name, kEngines[e].name,
                            bench_scene_figure_name(&s));
                continue;
            }
            double med = median(ms[e]), lo = minimum(ms[e]), f = median(fig[e]);
            /* Box2D v3 on 2 workers is set against ga2d on 2 */
            double ratio = (e == kV32w && !ms[kGa2d2w].empty() ? median(ms[kGa2d2w]) : ga2d_med) / med;
            bool own = e == 0 || e == kAvx2 || e == kGa2d2w; /* a ga2d build: no ratio against itself */
            char ratio_text[32], fig_text[32], avx2_text[32] = "";
            snprintf(ratio_text, sizeof ratio_text, own ? "-" : "%.2f", ratio);
            if (kAvx2 >= 0 && own) snprintf(avx2_text, sizeof avx2_text, "  %15s", "-");
            if (kAvx2 >= 0 && !own) snprintf(avx2_text, sizeof avx2_text, "  %15.2f", avx2_med / med);
            /* metres to the tenth of a millimetre; the momentum error is relative */
            snprintf(fig_text, sizeof fig_text, s.figure == BENCH_FIG_MOMENTUM ? "%.2e" : "%.4f", f);
            printf("  %-14s %-11s %12.3f %8.3f %10s %12s%s\n", s.name, kEngines[e].name, med, lo, ratio_text, fig_text,
                   avx2_text);
            notes += "    " + std::string(kEngines[e].name) + std::string(13 - strlen(kEngines[e].name), ' ') + check[e] + "\n";
            /* the figure is the median over runs; say so when runs disagree */
            double fmin = minimum(fig[e]), fmax = *std::max_element(fig[e].begin(), fig[e].end());
            if (fmax - fmin > 1e-9 + 1e-6 * std::fabs(fmax)) {
                char varies[100];
                snprintf(varies, sizeof varies, "              (its figure varies over runs: %.4g to %.4g)\n", fmin, fmax);
                notes += varies;
            }
            if (csv)
                fprintf(csv, "%s,%s,%.6f,%.6f,\"%s\",%.9g,%.6f,%.6f,%.6f\n", s.name, kEngines[e].name, med, lo,
                        bench_scene_figure_name(&s), f, own ? 1.0 : ratio, own || kAvx2 < 0 ? 1.0 : avx2_med / med,
                        med / v3_med);
        }
        if (kV3 >= 0) {
            double b2_med = ms[kBox2d].empty() ? NAN : median(ms[kBox2d]);
            printf("  %-14s ratios of medians: ga2d/v3 %.2f, v3/2.4.1 %.2f, ga2d/2.4.1 %.2f\n", s.name, ga2d_med / v3_med,
                   v3_med / b2_med, ga2d_med / b2_med);
        }
        {
            /* each engine's 1-worker time over its 2-worker time, from the medians */
            double w2 = ms[kGa2d2w].empty() ? NAN : median(ms[kGa2d2w]);
            double v3w2 = kV32w < 0 || ms[kV32w].empty() ? NAN : median(ms[kV32w]);
            printf("  %-14s 2 workers: ga2d %.2fx", s.name, ga2d_med / w2);
            if (kV32w >= 0) printf(", Box2D v3 %.2fx", v3_med / v3w2);
            printf(" the speed of 1 (1-worker median / 2-worker median)\n");
        }
        printf("  check (last run):\n%s", notes.c_str());
        fflush(stdout);
        bench_scene_free(&s);
    }
    printf("\ntotal %.1f s; CSV: %s\n", (now_ms() - t_start) / 1e3, csv ? csv_path : "(not written)");
    if (csv) fclose(csv);
    return failures ? 1 : 0;
}
