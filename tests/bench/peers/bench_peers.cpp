/* bench_peers.cpp - ga2d against Box2D 2.4.1 and Chipmunk 7 on the
   benchmark scenes of tests/bench/scenes.h (`make bench-peers`).

   Every engine builds the same list of bodies: boxes, or (joint_grid)
   bodies of one circle at their origin, and the scene's revolute joints
   (Box2D's b2RevoluteJoint, Chipmunk's pivot joint); for each scene the three
   engines run alternately (run r: ga2d, Box2D, Chipmunk, each with a fresh
   world; then ga2d built with -mavx2, where the CPU has AVX2), so a slow
   spell of the machine hits all of them.  Only the world
   step is timed, and not the first 10 steps (the first broadphase pass and
   warm-up); building, the tumbler's wall velocities and the accuracy
   figure are outside the clock.  Prints a table per scene and writes a CSV.

     peers [scene] [csv]   scene: one of scenes.h's names, or "all" (the
                           default); csv defaults to build/bench/peers.csv.
     BENCH_RUNS=n          runs per engine and scene (default 3). */
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
   bodies with shapes the runner builds); NULL for a box (no shapes of its
   own) or anything else (then the world is not built). */
static const bench_shape *lone_circle(const bench_scene &s, const bench_body &b)
{
    if (b.shape_count != 1) return NULL;
    const bench_shape *sh = &s.shapes[b.shape_first];
    return sh->kind == BENCH_SHAPE_CIRCLE && sh->x1 == 0 && sh->y1 == 0 ? sh : NULL;
}

/* A body the runner cannot build: shapes other than one centred circle. */
static bool unsupported(const bench_scene &s, const bench_body &b) { return b.shape_count > 0 && !lone_circle(s, b); }

/* One build of ga2d_peer.c: the generic one, or the -mavx2 one. */
struct Ga2dBuild {
    ga2d_peer *(*create)(double gx, double gy, int sleep, int capacity);
    int (*add_box)(ga2d_peer *p, int type, double x, double y, double hx, double hy, double vx, double vy, double w,
                   double density, double friction, int asleep);
    int (*add_circle)(ga2d_peer *p, int type, double x, double y, double radius, double density, double friction,
                      unsigned category, unsigned mask);
    int (*add_revolute)(ga2d_peer *p, int a, int b, double ax, double ay, double bx, double by);
    int (*step)(ga2d_peer *p, double dt);
    void (*pose)(const ga2d_peer *p, int i, double *x, double *y, double *angle);
    void (*velocity)(const ga2d_peer *p, int i, double *vx, double *vy);
    int (*is_awake)(const ga2d_peer *p, int i);
    void (*set_velocity)(ga2d_peer *p, int i, double vx, double vy, double w);
    void (*destroy)(ga2d_peer *p);
};

#define GA2D_BUILD(P)                                                                                               \
    {P##create,   P##add_box,  P##add_circle,   P##add_revolute, P##step,                                          \
     P##pose,     P##velocity, P##is_awake,     P##set_velocity, P##destroy}
static const Ga2dBuild kGa2dGeneric = GA2D_BUILD(ga2d_peer_);
#if PEERS_AVX2
static const Ga2dBuild kGa2dAvx2 = GA2D_BUILD(ga2d_peer_avx2_);
#endif

class Ga2dWorld : public World {
public:
    Ga2dWorld(const bench_scene &s, const Ga2dBuild &f) : f_(f), p_(f.create(s.gx, s.gy, s.sleep, s.count)), ok_(p_ != NULL)
    {
        for (int i = 0; ok_ && i < s.count; ++i) {
            const bench_body &b = s.bodies[i];
            const bench_shape *c = lone_circle(s, b);
            if (unsupported(s, b))
                ok_ = false;
            else if (c)
                ok_ = f_.add_circle(p_, b.type, b.x, b.y, c->radius, c->density, c->friction, c->category, c->mask) == i;
            else
                ok_ = f_.add_box(p_, b.type, b.x, b.y, b.hx, b.hy, b.vx, b.vy, b.w, b.density, b.friction, b.asleep) == i;
        }
        for (int i = 0; ok_ && i < s.joint_count; ++i) {
            const bench_joint &j = s.joints[i];
            ok_ = f_.add_revolute(p_, j.a, j.b, j.ax, j.ay, j.bx, j.by) == 0;
        }
    }
    ~Ga2dWorld() { f_.destroy(p_); }
    bool ok() const { return ok_; }
    bool step(double dt) { return f_.step(p_, dt) == 0; }
    void pose(int i, double *x, double *y, double *angle) const { f_.pose(p_, i, x, y, angle); }
    void velocity(int i, double *vx, double *vy) const { f_.velocity(p_, i, vx, vy); }
    void set_velocity(int i, double vx, double vy, double w) { f_.set_velocity(p_, i, vx, vy, w); }
    bool awake(int i) const { return f_.is_awake(p_, i) != 0; }

private:
    Ga2dWorld(const Ga2dWorld &);
    Ga2dWorld &operator=(const Ga2dWorld &);
    const Ga2dBuild &f_;
    ga2d_peer *p_;
    bool ok_;
};

class Box2dWorld : public World {
public:
    explicit Box2dWorld(const bench_scene &s) : world_(b2Vec2((float)s.gx, (float)s.gy)), ok_(true)
    {
        world_.SetAllowSleeping(s.sleep != 0);
        bodies_.reserve((size_t)s.count);
        for (int i = 0; i < s.count; ++i) {
            const bench_body &b = s.bodies[i];
            b2BodyDef bd;
            bd.type = b.type == BENCH_DYNAMIC ? b2_dynamicBody : b.type == BENCH_KINEMATIC ? b2_kinematicBody : b2_staticBody;
            bd.position.Set((float)b.x, (float)b.y);
            bd.linearVelocity.Set((float)b.vx, (float)b.vy);
            bd.angularVelocity = (float)b.w;
            bd.awake = !b.asleep;
            b2Body *body = world_.CreateBody(&bd);
            const bench_shape *c = lone_circle(s, b);
            b2PolygonShape box;
            b2CircleShape circle;
            b2FixtureDef fd;
            ok_ = ok_ && !unsupported(s, b);
            if (c) {
                circle.m_radius = (float)c->radius;
                fd.shape = &circle;
                fd.density = (float)c->density;
                fd.friction = (float)c->friction;
                /* Box2D 2.4's filter bits are 16 wide; the scenes use the low ones */
                fd.filter.categoryBits = (uint16)c->category;
                fd.filter.maskBits = (uint16)c->mask;
            } else {
                box.SetAsBox((float)b.hx, (float)b.hy);
                fd.shape = &box;
                fd.density = (float)b.density;
                fd.friction = (float)b.friction; /* Box2D mixes pairs as sqrt(mu_a mu_b) */
            }
            fd.restitution = 0;
            body->CreateFixture(&fd);
            bodies_.push_back(body);
        }
        for (int i = 0; ok_ && i < s.joint_count; ++i) {
            const bench_joint &j = s.joints[i];
            b2RevoluteJointDef jd; /* collideConnected false, no limit or motor */
            jd.bodyA = bodies_[(size_t)j.a];
            jd.bodyB = bodies_[(size_t)j.b];
            jd.localAnchorA.Set((float)j.ax, (float)j.ay);
            jd.localAnchorB.Set((float)j.bx, (float)j.by);
            jd.referenceAngle = jd.bodyB->GetAngle() - jd.bodyA->GetAngle();
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
    b2World world_; /* owns the bodies and joints */
    std::vector<b2Body *> bodies_;
    bool ok_;
};

class ChipmunkWorld : public World {
public:
    explicit ChipmunkWorld(const bench_scene &s) : space_(cpSpaceNew()), ok_(true)
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
            ok_ = ok_ && !unsupported(s, b);
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
static World *build_ga2d(const bench_scene &s) { return new Ga2dWorld(s, kGa2dGeneric); }
#if PEERS_AVX2
static World *build_ga2d_avx2(const bench_scene &s) { return new Ga2dWorld(s, kGa2dAvx2); }
#endif

struct Engine {
    const char *name;
    World *(*build)(const bench_scene &s);
};

/* ga2d first (its median is every ratio's numerator); ga2d's AVX2 build,
   where there is one, last, with its own ratios */
static const Engine kEngines[] = {{"ga2d", build_ga2d},
                                  {"Box2D", build<Box2dWorld>},
                                  {"Chipmunk", build<ChipmunkWorld>},
#if PEERS_AVX2
                                  {"ga2d-avx2", build_ga2d_avx2}
#endif
};
static const int kEngineCount = (int)(sizeof kEngines / sizeof kEngines[0]);
static const int kAvx2 = PEERS_AVX2 ? kEngineCount - 1 : -1; /* ga2d-avx2's index, -1 when not built */

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
    StderrCatcher caught;
    World *w = e.build(s);
    if (!w->ok()) {
        r.failed = "could not build the world";
        delete w;
        return r;
    }
    RunStats st = {0, 0, 0};
    for (int i = 0; i < s.count; ++i)
        if (s.bodies[i].asleep) {
            ++st.asleep_wanted;
            st.asleep_at_start += !w->awake(i);
        }
    std::vector<PlacedBox> boxes;
    std::vector<int> order;
    double total = 0, deepest = 0;
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
        if (s.figure == BENCH_FIG_PENETRATION) {
            place_boxes(s, *w, boxes);
            double d = deepest_overlap(boxes, order);
            deepest = std::max(deepest, d);
            st.deep_steps += d > kDeepOverlap;
        }
    }
    if (r.blown_up >= 0) {
        char line[160];
        snprintf(line, sizeof line, "blew up after step %d of %d: a body faster than %g m/s; no time, no figure",
                 r.blown_up + 1, s.steps, kBlownUpSpeed);
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
    else if (s.figure != BENCH_FIG_SAG)
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
static const char *const kScenes[] = {"large_pyramid", "many_pyramids", "smash", "tumbler", "pyramid20", "stack10",
                                     "joint_grid"};
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
    printf("bench-peers: ga2d vs Box2D %s vs Chipmunk %s\n", b2, cpVersionString);
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
           "            friction mixes as sqrt; continuous collision on (default); sleep: bd.awake = false\n",
           kBox2dVelocityIterations, kBox2dPositionIterations, (double)b2_polygonRadius, (double)b2_linearSlop);
    printf("            joints: b2RevoluteJoint (solved with the same iterations)\n");
    printf("  Chipmunk  %d iterations; cpBoxShapeNew radius 0; collision slop %.3f m; mass = density x area,\n"
           "            cpMomentForBox; shape friction sqrt(mu) (pairs multiply); sleep time %.1f s, bodies\n"
           "            put to sleep with cpBodySleep after they are added; cpFloat = %s; the library is\n"
           "            built with its debug checks (see its banner above); its warnings are counted per run\n",
           kChipmunkIterations, kChipmunkSlop, kChipmunkSleepTime, sizeof(cpFloat) == sizeof(double) ? "double" : "float");
    printf("            joints: cpPivotJointNew2 at the two anchors (default error bias, max force infinite)\n");
    printf("figures, measured alike in every engine from its poses and velocities:\n"
           "  drift: the top box's distance from its start at the end (m); Box2D's boxes rest on their skins,\n"
           "    so its stacks stand about 0.013 m per layer higher than they were built\n"
           "  momentum: |sum m v - P0| / |P0| at the end, m = density x area from the scene\n"
           "  penetration: the deepest overlap, over every step, of two of the scene's boxes at their\n"
           "    nominal size (Box2D's 0.01 m skin is not part of the box), one of them dynamic (m)\n"
           "  sag: how far the joint grid's bottom corner ends below its start (m); the check gives the\n"
           "    worst joint separation at the end: the largest distance between a joint's two anchors\n"
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
    const char *only = argc > 1 && strcmp(argv[1], "all") != 0 ? argv[1] : NULL;
    const char *csv_path = argc > 2 ? argv[2] : "build/bench/peers.csv";
    if (only) {
        bool known = false;
        for (int k = 0; k < kSceneCount; ++k) known = known || strcmp(only, kScenes[k]) == 0;
        if (!known) {
            fprintf(stderr, "peers: unknown scene '%s'; scenes:", only);
            for (int k = 0; k < kSceneCount; ++k) fprintf(stderr, " %s", kScenes[k]);
            fprintf(stderr, " (or all)\n");
            return 2;
        }
    }
    FILE *csv = fopen(csv_path, "w");
    if (!csv) fprintf(stderr, "peers: cannot write %s; no CSV this time\n", csv_path);
    if (csv) fprintf(csv, "scene,engine,ms_median,ms_min,figure_name,figure,ratio,ratio_avx2\n");

    /* Chipmunk greets on its first space; let that happen before the tables */
    cpSpaceFree(cpSpaceNew());
    print_header(runs);
    if (runs < 3) printf("note: fewer than 3 runs, so the medians are not robust\n");
    double t_start = now_ms();
    int failures = 0;
    for (int k = 0; k < kSceneCount; ++k) {
        if (only && strcmp(only, kScenes[k]) != 0) continue;
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
        for (int r = 0; r < runs; ++r)
            for (int e = 0; e < kEngineCount; ++e) {
                if (!failed[e].empty() || !blown[e].empty()) continue;
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
        printf("  %-14s %-9s %12s %8s %10s %12s%s\n", "scene", "engine", "ms/step med", "min", "ga2d/peer", "figure",
               kAvx2 >= 0 ? "  ga2d-avx2/peer" : "");
        double ga2d_med = ms[0].empty() ? NAN : median(ms[0]);
        double avx2_med = kAvx2 < 0 || ms[kAvx2].empty() ? NAN : median(ms[kAvx2]);
        std::string notes;
        for (int e = 0; e < kEngineCount; ++e) {
            if (!failed[e].empty()) {
                printf("  %-14s %-9s FAILED: %s\n", s.name, kEngines[e].name, failed[e].c_str());
                ++failures;
                continue;
            }
            if (!blown[e].empty()) {
                printf("  %-14s %-9s %s\n", s.name, kEngines[e].name, blown[e].c_str());
                if (csv)
                    fprintf(csv, "%s,%s,nan,nan,\"%s\",nan,nan,nan\n", s.name, kEngines[e].name,
                            bench_scene_figure_name(&s));
                continue;
            }
            double med = median(ms[e]), lo = minimum(ms[e]), f = median(fig[e]);
            double ratio = ga2d_med / med;
            bool own = e == 0 || e == kAvx2; /* a ga2d build: no ratio against itself */
            char ratio_text[32], fig_text[32], avx2_text[32] = "";
            snprintf(ratio_text, sizeof ratio_text, own ? "-" : "%.2f", ratio);
            if (kAvx2 >= 0 && own) snprintf(avx2_text, sizeof avx2_text, "  %15s", "-");
            if (kAvx2 >= 0 && !own) snprintf(avx2_text, sizeof avx2_text, "  %15.2f", avx2_med / med);
            /* metres to the tenth of a millimetre; the momentum error is relative */
            snprintf(fig_text, sizeof fig_text, s.figure == BENCH_FIG_MOMENTUM ? "%.2e" : "%.4f", f);
            printf("  %-14s %-9s %12.3f %8.3f %10s %12s%s\n", s.name, kEngines[e].name, med, lo, ratio_text, fig_text,
                   avx2_text);
            notes += "    " + std::string(kEngines[e].name) + std::string(10 - strlen(kEngines[e].name), ' ') + check[e] + "\n";
            /* the figure is the median over runs; say so when runs disagree */
            double fmin = minimum(fig[e]), fmax = *std::max_element(fig[e].begin(), fig[e].end());
            if (fmax - fmin > 1e-9 + 1e-6 * std::fabs(fmax)) {
                char varies[100];
                snprintf(varies, sizeof varies, "              (its figure varies over runs: %.4g to %.4g)\n", fmin, fmax);
                notes += varies;
            }
            if (csv)
                fprintf(csv, "%s,%s,%.6f,%.6f,\"%s\",%.9g,%.6f,%.6f\n", s.name, kEngines[e].name, med, lo,
                        bench_scene_figure_name(&s), f, own ? 1.0 : ratio, own || kAvx2 < 0 ? 1.0 : avx2_med / med);
        }
        printf("  check (last run):\n%s", notes.c_str());
        fflush(stdout);
        bench_scene_free(&s);
    }
    printf("\ntotal %.1f s; CSV: %s\n", (now_ms() - t_start) / 1e3, csv ? csv_path : "(not written)");
    if (csv) fclose(csv);
    return failures ? 1 : 0;
}
