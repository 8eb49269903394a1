/* far_origin.c - how float holds up far from the origin (the README's
   table under Limitations).  At each x: a disc (r 0.5 m) rolling at 2 m/s
   without slipping on a static box whose top is y = 0 and whose centre is
   at x, from x - 10 for 10 s, and a 1 m box resting on it at x + 30;
   defaults, sleep off.  Prints the rolling error (distance / (v t) - 1),
   how deep the disc sank after the first second, and how far the resting
   box moved over the last 5 s.

     make build/examples/far_origin && ./build/examples/far_origin
   and for double, the same file built with -DGA2D_DOUBLE. */
#define GA2D_IMPLEMENTATION
#include "ga2d_physics.h"

#include <math.h>
#include <stdio.h>

static ga2d_vec vec(double x, double y) { return ga2d_vec_make((ga2d_real)x, (ga2d_real)y); }

static void run(double X)
{
    const double v0 = 2, r = 0.5, T = 10;
    const int steps = 600;
    double sink = 0, moved = 0;
    ga2d_world_def wd = ga2d_default_world_def();
    ga2d_world *w;
    ga2d_body_def d;
    ga2d_shape_def sd = ga2d_default_shape_def();
    ga2d_circle c;
    ga2d_body_id disc, box;
    ga2d_vec x0, b0 = vec(0, 0);
    int s;
    wd.enable_sleep = 0;
    w = ga2d_world_create(&wd);
    if (!w) return;
    d = ga2d_default_body_def();
    d.position = vec(X, -0.5);
    d.polygon = ga2d_polygon_box(50, (ga2d_real)0.5);
    d.friction = (ga2d_real)0.6;
    ga2d_body_create(w, &d);
    d = ga2d_default_body_def();
    d.type = GA2D_BODY_DYNAMIC;
    d.position = vec(X - 10, r);
    d.velocity = vec(v0, 0);
    d.angular_velocity = (ga2d_real)(-v0 / r);
    disc = ga2d_body_create(w, &d);
    sd.friction = (ga2d_real)0.6;
    c.center = vec(0, 0);
    c.radius = (ga2d_real)r;
    ga2d_shape_create_circle(w, disc, &sd, &c);
    d = ga2d_default_body_def();
    d.type = GA2D_BODY_DYNAMIC;
    d.position = vec(X + 30, 0.5);
    d.polygon = ga2d_polygon_box((ga2d_real)0.5, (ga2d_real)0.5);
    d.friction = (ga2d_real)0.6;
    box = ga2d_body_create(w, &d);
    x0 = ga2d_body_position(w, disc);
    for (s = 0; s < steps; ++s) {
        ga2d_vec p;
        if (ga2d_world_step(w, (ga2d_real)(1.0 / 60)) != GA2D_OK) break;
        p = ga2d_body_position(w, disc);
        if (s >= 60 && r - (double)p.y > sink) sink = r - (double)p.y;
        if (s == steps / 2 - 1) b0 = ga2d_body_position(w, box);
        if (s >= steps / 2) {
            ga2d_vec q = ga2d_body_position(w, box);
            double m = fabs((double)q.x - (double)b0.x) + fabs((double)q.y - (double)b0.y);
            if (m > moved) moved = m;
        }
    }
    printf("| %7.0e | %+.2e | %.1e | %.0e |\n", X,
           ((double)ga2d_body_position(w, disc).x - (double)x0.x) / (v0 * T) - 1, sink, moved);
    ga2d_world_destroy(w);
}

int main(void)
{
    static const double xs[] = {0, 1e3, 1e4, 3e4, 1e5, 3e5, 1e6};
    size_t k;
    printf("ga2d_real = %s\n| x (m) | rolling error | sank (m) | box moved (m) |\n|---|---|---|---|\n",
           sizeof(ga2d_real) == sizeof(double) ? "double" : "float");
    for (k = 0; k < sizeof xs / sizeof xs[0]; ++k) run(xs[k]);
    return 0;
}
