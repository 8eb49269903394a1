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

/* A world from ga2d_default_world_def() with this gravity and sleep
   switch, room for `capacity` bodies; NULL on failure. */
ga2d_peer *ga2d_peer_create(double gx, double gy, int sleep, int capacity);
/* A box body of half-extents hx, hy centred at (x, y); restitution 0.
   Returns its index, or -1 when ga2d refuses it. */
int ga2d_peer_add_box(ga2d_peer *p, int type, double x, double y, double hx, double hy, double vx, double vy,
                      double w, double density, double friction, int asleep);
int ga2d_peer_step(ga2d_peer *p, double dt); /* 0, or ga2d's error code */
void ga2d_peer_pose(const ga2d_peer *p, int i, double *x, double *y, double *angle);
void ga2d_peer_velocity(const ga2d_peer *p, int i, double *vx, double *vy);
int ga2d_peer_is_awake(const ga2d_peer *p, int i);
void ga2d_peer_set_velocity(ga2d_peer *p, int i, double vx, double vy, double w);
void ga2d_peer_destroy(ga2d_peer *p);

const char *ga2d_peer_compiler(void); /* the compiler that built ga2d_peer.c */
int ga2d_peer_real_is_double(void);   /* 1 under GA2D_DOUBLE, else 0 (float) */
const char *ga2d_peer_settings(void); /* one line: the world settings used */

#ifdef __cplusplus
}
#endif

#endif
