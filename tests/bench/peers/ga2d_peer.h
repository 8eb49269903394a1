/* ga2d_peer.h - ga2d seen by the peer benchmark (bench_peers.cpp).

   ga2d is compiled as C99 in its own translation unit (ga2d_peer.c, the
   library's float build), so the C++ driver reaches it only through these
   plain functions, with doubles at the boundary.  Body indices are the
   order of ga2d_peer_add_box calls (the scene's order); body types are
   scenes.h's BENCH_STATIC / BENCH_KINEMATIC / BENCH_DYNAMIC. */
#ifndef GA2D_PEER_H
#define GA2D_PEER_H

#ifdef __cplusplus
extern "C" {
#endif

typedef struct ga2d_peer ga2d_peer;

/* The functions, declared once per build of ga2d_peer.c: prefix
   ga2d_peer_ for the generic build, ga2d_peer_avx2_ for the one compiled
   with -mavx2 (GA2D_PEER_AVX2 defined; 8 float lanes), which the Makefile
   adds where the CPU has AVX2.  Per function:
     create        a world from ga2d_default_world_def() with this gravity
                   and sleep switch, room for `capacity` bodies; NULL on
                   failure;
     add_box       a box body of half-extents hx, hy centred at (x, y),
                   restitution 0; its index, or -1 when ga2d refuses it;
     add_circle    a body at (x, y) with one circle of this radius at its
                   origin, filter category and mask as given, restitution
                   0; its index, or -1;
     add_revolute  a revolute joint between bodies a and b (indices) at
                   anchor (ax, ay) of a's frame and (bx, by) of b's,
                   the defaults otherwise; 0, or -1 when ga2d refuses it;
     step          0, or ga2d's error code;
     compiler      the compiler that built ga2d_peer.c;
     real_is_double  1 under GA2D_DOUBLE, else 0 (float);
     settings      one line: the world settings used. */
#define GA2D_PEER_FUNCTIONS(P)                                                                                   \
    ga2d_peer *P##create(double gx, double gy, int sleep, int capacity);                                         \
    int P##add_box(ga2d_peer *p, int type, double x, double y, double hx, double hy, double vx, double vy,         \
                   double w, double density, double friction, int asleep);                                       \
    int P##add_circle(ga2d_peer *p, int type, double x, double y, double radius, double density, double friction, \
                      unsigned category, unsigned mask);                                                         \
    int P##add_revolute(ga2d_peer *p, int a, int b, double ax, double ay, double bx, double by);                 \
    int P##step(ga2d_peer *p, double dt);                                                                        \
    void P##pose(const ga2d_peer *p, int i, double *x, double *y, double *angle);                                \
    void P##velocity(const ga2d_peer *p, int i, double *vx, double *vy);                                         \
    int P##is_awake(const ga2d_peer *p, int i);                                                                  \
    void P##set_velocity(ga2d_peer *p, int i, double vx, double vy, double w);                                   \
    void P##destroy(ga2d_peer *p);                                                                               \
    const char *P##compiler(void);                                                                               \
    int P##real_is_double(void);                                                                                 \
    const char *P##settings(void);

GA2D_PEER_FUNCTIONS(ga2d_peer_)
GA2D_PEER_FUNCTIONS(ga2d_peer_avx2_)

#ifdef __cplusplus
}
#endif

#endif
