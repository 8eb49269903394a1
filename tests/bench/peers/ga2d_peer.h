/* ga2d_peer.h - the C engines seen by the peer benchmark (bench_peers.cpp).

   ga2d is compiled as C99 in its own translation unit (ga2d_peer.c, the
   library's float build), and Box2D v3, when `make bench-peers` is given
   its sources (B2V3_SRC), in another (b2v3_peer.c, C17, against v3's own
   headers, which clash with Box2D 2.4.1's C++ ones), so the C++ driver
   reaches them only through these plain functions, with doubles at the
   boundary.  Body indices are the order of add_box / add_body calls (the
   scene's order); body types are scenes.h's BENCH_STATIC /
   BENCH_KINEMATIC / BENCH_DYNAMIC, shape kinds its BENCH_SHAPE_*. */
#ifndef GA2D_PEER_H
#define GA2D_PEER_H

#ifdef __cplusplus
extern "C" {
#endif

typedef struct ga2d_peer ga2d_peer;

/* The functions, declared once per build with prefix P and world type T:
   ga2d_peer_ for ga2d's generic build, ga2d_peer_avx2_ for the one
   compiled with -mavx2 (GA2D_PEER_AVX2 defined; 8 float lanes), which the
   Makefile adds where the CPU has AVX2, and b2v3_peer_ (type b2v3_peer)
   for Box2D v3.  Per function:
     use_workers   the worker count of the worlds created from now on (1,
                   the default: the step runs on the calling thread; more:
                   ga2d on a task_pool of examples/task_pool.h, Box2D v3 on
                   its built-in scheduler);
     create        a world from the engine's default world def with this
                   gravity and sleep switch and the worker count set, room
                   for `capacity` bodies; NULL on failure;
     add_box       a box body of half-extents hx, hy centred at (x, y),
                   restitution 0; its index, or -1 when the engine refuses it;
     add_body      a body with no shape yet at origin (x, y), turned by
                   `angle`, with this velocity and linear damping, created
                   asleep if asked, never sleeping if never_sleeps (where
                   the engine has that switch; ga2d has not); its index,
                   or -1;
     add_shape     a shape on body i, in its frame (scenes.h's bench_shape:
                   a circle at (x1, y1), a capsule from (x1, y1) to
                   (x2, y2), of this radius; a convex polygon of `count`
                   points px, py counter-clockwise, rounded by radius),
                   with its material and filter; 0, or -1;
     add_chain_loop  a closed chain of one-sided segments on body i
                   through `count` points wound clockwise, solid to the
                   right (scenes.h's chain), with this friction; 0, or -1;
     add_revolute  a revolute joint between bodies a and b (indices) at
                   anchor (ax, ay) of a's frame and (bx, by) of b's, with
                   a motor toward motor_speed of at most max_motor_torque
                   when `motor`, the defaults otherwise; 0, or -1 when
                   the engine refuses it;
     step          0, or ga2d's error code;
     compiler      the compiler that built ga2d_peer.c;
     real_is_double  1 under GA2D_DOUBLE, else 0 (float);
     settings      one line: the world settings used. */
#define GA2D_PEER_FUNCTIONS(P, T)                                                                                \
    void P##use_workers(int workers);                                                                            \
    T *P##create(double gx, double gy, int sleep, int capacity);                                                 \
    int P##add_box(T *p, int type, double x, double y, double hx, double hy, double vx, double vy, double w,      \
                   double density, double friction, int asleep);                                                 \
    int P##add_body(T *p, int type, double x, double y, double angle, double vx, double vy, double w,            \
                    double linear_damping, int asleep, int never_sleeps);                                        \
    int P##add_shape(T *p, int i, int kind, double x1, double y1, double x2, double y2, double radius, int count, \
                     const double *px, const double *py, double density, double friction, double restitution,    \
                     int group, unsigned category, unsigned mask);                                               \
    int P##add_chain_loop(T *p, int i, int count, const double *x, const double *y, double friction);             \
    int P##add_revolute(T *p, int a, int b, double ax, double ay, double bx, double by, int motor,                \
                        double motor_speed, double max_motor_torque);                                            \
    int P##step(T *p, double dt);                                                                                \
    void P##pose(const T *p, int i, double *x, double *y, double *angle);                                        \
    void P##velocity(const T *p, int i, double *vx, double *vy);                                                 \
    int P##is_awake(const T *p, int i);                                                                          \
    void P##set_velocity(T *p, int i, double vx, double vy, double w);                                           \
    void P##destroy(T *p);                                                                                       \
    const char *P##compiler(void);                                                                               \
    int P##real_is_double(void);                                                                                 \
    const char *P##settings(void);

GA2D_PEER_FUNCTIONS(ga2d_peer_, ga2d_peer)
GA2D_PEER_FUNCTIONS(ga2d_peer_avx2_, ga2d_peer)

typedef struct b2v3_peer b2v3_peer;
GA2D_PEER_FUNCTIONS(b2v3_peer_, b2v3_peer)

#ifdef __cplusplus
}
#endif

#endif
