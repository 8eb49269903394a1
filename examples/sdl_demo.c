/* sdl_demo.c - an interactive window onto ga2d_physics.h, drawn with SDL2.

   Eleven scenes on the number keys and J; drag a body with the left mouse
   button (a motor joint from a static body drives the grabbed point to the
   cursor, with at most DRAG_WEIGHTS times the body's weight); throw a 1 m
   box with the right button
   (press where it starts, drag to aim, release to throw); switch substeps,
   solver and sleep while it runs and watch the time per step change.

     1-5  scene: pyramid, stack of 10, Newton's cradle, incline, bounce
     6-0  shapes: a ball rolls beside a sliding box (6), a pile of circles,
          capsules, boxes and rounded polygons poured into a bin (7), a
          half-pipe of one loop chain (8), a sensor zone counting what
          passes (9), a one-way platform by pre-solve, with hit events (0)
     J    joints: a bridge of 20 planks on revolute joints under three
          boxes, and a chain of 12 links holding a heavy ball
     R    reset the scene          P  pause        C  contact points
     S    substeps 1/2/4/8         V  solver: soft step / PGS+Baumgarte / PGS+NGS
     Z    sleep on/off             Esc quit

   Everything on screen goes through the library's debug draw
   (ga2d_world_draw with the GA2D_COLOR_* state colours): polygons (rounded
   ones with their arcs), circles with a radius line that shows them roll,
   capsules, and segments (chains); the sensor zone is drawn see-through
   and what it holds in blue.  Text is a 5x7 bitmap font drawn as filled
   rectangles, so only SDL2 itself is needed.

   Build (needs Debian's libsdl2-dev, SDL 2.0.18 or newer):
     gcc -std=c99 -O2 -I. examples/sdl_demo.c $(sdl2-config --cflags --libs) -lm

   Options, for scripted runs (e.g. under Xvfb):
     --scene N          start in scene N (1-11; 10 is key 0, 11 is J)
     --frames N         run N frames, one fixed step each, then quit
     --screenshot FILE  save the last frame as a BMP (default 120 frames)
     --drag-test        grab the top body at frame 20 and pull it 5 m aside, 1.5 m up
     --throw-test       throw a box into the scene at frame 10
     --substeps N, --solver soft|baumgarte|ngs, --no-sleep, --contacts */
#define GA2D_IMPLEMENTATION
#include "ga2d_physics.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <SDL.h>

#if !SDL_VERSION_ATLEAST(2, 0, 18)
#error "sdl_demo needs SDL 2.0.18 or newer (SDL_RenderGeometry)"
#endif

#define WINDOW_W 1280
#define WINDOW_H 720
#define HUD_TOP 64     /* pixels of text at the top */
#define HUD_BOTTOM 30  /* and at the bottom */
#define STEP_DT (1.0 / 60.0)
#define MAX_BODIES 4096
#define TIMING_WINDOW 60 /* steps in the ms/step moving average */
#define DRAG_WEIGHTS 20.0 /* the mouse drag's max force, in the body's weights (m g) */
#define DRAG_SPIN 5.0     /* its max torque over the body's inertia, rad/s^2: a
                             spin brake, weak enough to let it swing */
#define PI_D 3.14159265358979323846

/* ===================================================================== font */
/* 5x7 glyphs, one 35-character string each, rows top to bottom ('#' = on).
   Lower case is drawn as upper case. */
typedef struct glyph { char c; const char *rows; } glyph;
static const glyph FONT[] = {
    {'0', ".###." "#...#" "#..##" "#.#.#" "##..#" "#...#" ".###."},
    {'1', "..#.." ".##.." "..#.." "..#.." "..#.." "..#.." ".###."},
    {'2', ".###." "#...#" "....#" "...#." "..#.." ".#..." "#####"},
    {'3', "#####" "...#." "..#.." "...#." "....#" "#...#" ".###."},
    {'4', "...#." "..##." ".#.#." "#..#." "#####" "...#." "...#."},
    {'5', "#####" "#...." "####." "....#" "....#" "#...#" ".###."},
    {'6', "..##." ".#..." "#...." "####." "#...#" "#...#" ".###."},
    {'7', "#####" "....#" "...#." "..#.." ".#..." ".#..." ".#..."},
    {'8', ".###." "#...#" "#...#" ".###." "#...#" "#...#" ".###."},
    {'9', ".###." "#...#" "#...#" ".####" "....#" "...#." ".##.."},
    {'A', ".###." "#...#" "#...#" "#...#" "#####" "#...#" "#...#"},
    {'B', "####." "#...#" "#...#" "####." "#...#" "#...#" "####."},
    {'C', ".###." "#...#" "#...." "#...." "#...." "#...#" ".###."},
    {'D', "###.." "#..#." "#...#" "#...#" "#...#" "#..#." "###.."},
    {'E', "#####" "#...." "#...." "####." "#...." "#...." "#####"},
    {'F', "#####" "#...." "#...." "####." "#...." "#...." "#...."},
    {'G', ".###." "#...#" "#...." "#.###" "#...#" "#...#" ".####"},
    {'H', "#...#" "#...#" "#...#" "#####" "#...#" "#...#" "#...#"},
    {'I', ".###." "..#.." "..#.." "..#.." "..#.." "..#.." ".###."},
    {'J', "..###" "...#." "...#." "...#." "...#." "#..#." ".##.."},
    {'K', "#...#" "#..#." "#.#.." "##..." "#.#.." "#..#." "#...#"},
    {'L', "#...." "#...." "#...." "#...." "#...." "#...." "#####"},
    {'M', "#...#" "##.##" "#.#.#" "#.#.#" "#...#" "#...#" "#...#"},
    {'N', "#...#" "#...#" "##..#" "#.#.#" "#..##" "#...#" "#...#"},
    {'O', ".###." "#...#" "#...#" "#...#" "#...#" "#...#" ".###."},
    {'P', "####." "#...#" "#...#" "####." "#...." "#...." "#...."},
    {'Q', ".###." "#...#" "#...#" "#...#" "#.#.#" "#..#." ".##.#"},
    {'R', "####." "#...#" "#...#" "####." "#.#.." "#..#." "#...#"},
    {'S', ".####" "#...." "#...." ".###." "....#" "....#" "####."},
    {'T', "#####" "..#.." "..#.." "..#.." "..#.." "..#.." "..#.."},
    {'U', "#...#" "#...#" "#...#" "#...#" "#...#" "#...#" ".###."},
    {'V', "#...#" "#...#" "#...#" "#...#" "#...#" ".#.#." "..#.."},
    {'W', "#...#" "#...#" "#...#" "#.#.#" "#.#.#" "#.#.#" ".#.#."},
    {'X', "#...#" "#...#" ".#.#." "..#.." ".#.#." "#...#" "#...#"},
    {'Y', "#...#" "#...#" ".#.#." "..#.." "..#.." "..#.." "..#.."},
    {'Z', "#####" "....#" "...#." "..#.." ".#..." "#...." "#####"},
    {'.', "....." "....." "....." "....." "....." ".##.." ".##.."},
    {',', "....." "....." "....." "....." ".##.." "..#.." ".#..."},
    {':', "....." ".##.." ".##.." "....." ".##.." ".##.." "....."},
    {'-', "....." "....." "....." "#####" "....." "....." "....."},
    {'+', "....." "..#.." "..#.." "#####" "..#.." "..#.." "....."},
    {'/', "....." "....#" "...#." "..#.." ".#..." "#...." "....."},
    {'(', "...#." "..#.." ".#..." ".#..." ".#..." "..#.." "...#."},
    {')', ".#..." "..#.." "...#." "...#." "...#." "..#.." ".#..."},
    {'[', ".###." ".#..." ".#..." ".#..." ".#..." ".#..." ".###."},
    {']', ".###." "...#." "...#." "...#." "...#." "...#." ".###."},
    {'<', "...#." "..#.." ".#..." "#...." ".#..." "..#.." "...#."},
    {'>', ".#..." "..#.." "...#." "....#" "...#." "..#.." ".#..."},
    {'=', "....." "....." "#####" "....." "#####" "....." "....."},
    {'%', "##..." "##..#" "...#." "..#.." ".#..." "#..##" "...##"},
    {'!', "..#.." "..#.." "..#.." "..#.." "..#.." "....." "..#.."},
    {'?', ".###." "#...#" "....#" "...#." "..#.." "....." "..#.."},
    {'\'', "..#.." "..#.." ".#..." "....." "....." "....." "....."},
    {'_', "....." "....." "....." "....." "....." "....." "#####"},
    {'*', "....." "..#.." "#.#.#" ".###." "#.#.#" "..#.." "....."},
    {'|', "..#.." "..#.." "..#.." "..#.." "..#.." "..#.." "..#.."},
};

static const char *glyph_rows(char c)
{
    size_t i;
    if (c >= 'a' && c <= 'z') c = (char)(c - 'a' + 'A');
    for (i = 0; i < sizeof FONT / sizeof FONT[0]; ++i)
        if (FONT[i].c == c) return FONT[i].rows;
    return NULL; /* space, and anything unknown, is blank */
}

/* Width in pixels of s drawn at this scale: 6 cells per character. */
static int text_width(const char *s, int scale) { return (int)strlen(s) * 6 * scale; }

/* Draws s with its top-left corner at (x, y), each cell scale x scale
   pixels, batched into SDL_RenderFillRects calls. */
static void draw_text(SDL_Renderer *r, int x, int y, int scale, const char *s, SDL_Color col)
{
    SDL_Rect cells[512];
    int n = 0, k;
    SDL_SetRenderDrawColor(r, col.r, col.g, col.b, col.a);
    for (; *s; ++s, x += 6 * scale) {
        const char *rows = glyph_rows(*s);
        if (!rows) continue;
        for (k = 0; k < 35; ++k) {
            if (rows[k] != '#') continue;
            if (n == (int)(sizeof cells / sizeof cells[0])) {
                SDL_RenderFillRects(r, cells, n);
                n = 0;
            }
            cells[n].x = x + (k % 5) * scale;
            cells[n].y = y + (k / 5) * scale;
            cells[n].w = cells[n].h = scale;
            ++n;
        }
    }
    if (n > 0) SDL_RenderFillRects(r, cells, n);
}

/* Text with a one-pixel dark shadow, readable over any body colour. */
static void draw_text_shadowed(SDL_Renderer *r, int x, int y, int scale, const char *s, SDL_Color col)
{
    SDL_Color shadow = {0, 0, 0, 255};
    draw_text(r, x + 1, y + 1, scale, s, shadow);
    draw_text(r, x, y, scale, s, col);
}

/* =================================================================== camera */
/* World metres (y up) to window pixels (y down). */
typedef struct camera { double cx, cy, scale; } camera;

static camera camera_fit(double xmin, double ymin, double xmax, double ymax)
{
    camera c;
    double view_w = WINDOW_W - 40, view_h = WINDOW_H - HUD_TOP - HUD_BOTTOM - 20;
    double sx = view_w / (xmax - xmin), sy = view_h / (ymax - ymin);
    c.scale = sx < sy ? sx : sy;
    c.cx = 0.5 * (xmin + xmax);
    c.cy = 0.5 * (ymin + ymax);
    return c;
}

static SDL_FPoint to_screen(const camera *c, ga2d_vec p)
{
    SDL_FPoint s;
    double mid_y = HUD_TOP + 0.5 * (WINDOW_H - HUD_TOP - HUD_BOTTOM);
    s.x = (float)(0.5 * WINDOW_W + ((double)p.x - c->cx) * c->scale);
    s.y = (float)(mid_y - ((double)p.y - c->cy) * c->scale);
    return s;
}

static ga2d_vec to_world(const camera *c, double sx, double sy)
{
    double mid_y = HUD_TOP + 0.5 * (WINDOW_H - HUD_TOP - HUD_BOTTOM);
    return ga2d_vec_make((ga2d_real)(c->cx + (sx - 0.5 * WINDOW_W) / c->scale),
                         (ga2d_real)(c->cy - (sy - mid_y) / c->scale));
}

/* ====================================================================== app */
typedef struct label { ga2d_vec at; char text[32]; } label;

static const int SUBSTEP_CHOICES[] = {1, 2, 4, 8};
static const char *const SOLVER_NAMES[GA2D_SOLVER_COUNT] = {"SOFT STEP", "PGS+BAUMGARTE", "PGS+NGS"};
#define SCENES 11
static const char *const SCENE_NAMES[SCENES + 1] = {"", "PYRAMID (BASE 20)", "STACK OF 10", "NEWTON'S CRADLE",
                                                    "INCLINE: THREE FRICTIONS", "BOUNCE: THREE RESTITUTIONS",
                                                    "ROLL: BALL AND BOX ON 20 DEGREES", "PILE OF SHAPES",
                                                    "TERRAIN: ONE LOOP CHAIN", "SENSOR ZONE",
                                                    "ONE-WAY PLATFORM, HIT EVENTS",
                                                    "JOINTS: BRIDGE AND CHAIN"};

typedef struct app {
    SDL_Renderer *ren;
    ga2d_world *world;
    int scene;
    camera cam;
    label labels[8];
    int label_count;

    /* settings that survive a scene change */
    int substep_index; /* into SUBSTEP_CHOICES */
    ga2d_solver solver;
    int sleep_on, paused, show_contacts;

    /* the dynamic bodies we made, for removing the ones that fall off */
    ga2d_body_id bodies[MAX_BODIES];
    int body_count;

    /* left-drag: a motor joint from a static body (at the grab point) to
       the grabbed body, its target moved to the cursor every step */
    ga2d_vec cursor;   /* world */
    int dragging;
    ga2d_body_id grab;
    ga2d_vec grab_local; /* the grabbed point in the body's frame */
    ga2d_body_id mouse;  /* the static body: no shape, at the grab point */
    ga2d_joint_id drag;

    /* right-drag: aim a throw */
    int aiming;
    ga2d_vec aim_from;

    /* ms per ga2d_world_step: the last TIMING_WINDOW steps */
    double step_ms[TIMING_WINDOW];
    int step_ms_count, step_ms_next;

    /* the shape scenes (6-10): a status line, steps since the scene began,
       things poured or thrown so far, the sensor zone and what it holds,
       the platform, and the events counted */
    char status[128];
    int scene_steps, spawned;
    unsigned rng;
    ga2d_body_id zone;
    ga2d_shape_id zone_shape, platform;
    ga2d_body_id inside[64];
    int inside_count, entered, left, hits;
    double last_hit;
    int last_hit_on_platform;
} app;

static void remember(app *a, ga2d_body_id id)
{
    if (!ga2d_body_id_is_null(id) && a->body_count < MAX_BODIES) a->bodies[a->body_count++] = id;
}

static void add_label(app *a, ga2d_real x, ga2d_real y, const char *text)
{
    if (a->label_count >= (int)(sizeof a->labels / sizeof a->labels[0])) return;
    a->labels[a->label_count].at = ga2d_vec_make(x, y);
    snprintf(a->labels[a->label_count].text, sizeof a->labels[0].text, "%s", text);
    ++a->label_count;
}

static ga2d_body_id add_box(app *a, ga2d_body_type type, ga2d_real x, ga2d_real y, ga2d_real hw, ga2d_real hh,
                            ga2d_real angle, ga2d_real friction, ga2d_real restitution)
{
    ga2d_body_def bd = ga2d_default_body_def();
    ga2d_body_id id;
    bd.type = type;
    bd.position = ga2d_vec_make(x, y);
    bd.rotor = ga2d_rotor_from_angle(angle);
    bd.polygon = ga2d_polygon_box(hw, hh);
    bd.friction = friction;
    bd.restitution = restitution;
    id = ga2d_body_create(a->world, &bd);
    if (type == GA2D_BODY_DYNAMIC) remember(a, id);
    return id;
}

/* The Box2D ground: a static box of half-extents 100 x 1, its top at y = 0. */
static void add_ground(app *a, ga2d_real friction)
{
    add_box(a, GA2D_BODY_STATIC, 0, -1, 100, 1, 0, friction, 0);
}

/* ------------------------------------------------------------ shape scenes */
#define BIN_HALF_W 6.0   /* scene 7: the bin's inside half-width */
#define POUR_TOTAL 150   /* scene 7: bodies poured */
#define ZONE_BOTTOM 3.0  /* scene 9: the sensor zone, y = 3 .. 5 */
#define ZONE_TOP 5.0
#define PLATFORM_TOP 3.1 /* scene 10: the one-way platform's top */
#define INSIDE_COLOR 0x4C8CE5u

/* In [0, 1): a 32-bit LCG, so a scene pours the same pile every time. */
static double app_random(app *a)
{
    a->rng = a->rng * 1664525u + 1013904223u;
    return (double)(a->rng >> 8) / 16777216.0;
}

/* A body with no shape yet (the default def has none) at (x, y), turned by
   angle, moving at v. */
static ga2d_body_id add_body(app *a, ga2d_body_type type, double x, double y, double angle, ga2d_vec v)
{
    ga2d_body_def bd = ga2d_default_body_def();
    ga2d_body_id id;
    bd.type = type;
    bd.position = ga2d_vec_make((ga2d_real)x, (ga2d_real)y);
    bd.rotor = ga2d_rotor_from_angle((ga2d_real)angle);
    bd.velocity = v;
    id = ga2d_body_create(a->world, &bd);
    if (type == GA2D_BODY_DYNAMIC) remember(a, id);
    return id;
}

static ga2d_shape_id add_circle(app *a, ga2d_body_id body, double r, const ga2d_shape_def *sd)
{
    ga2d_circle c;
    c.center = ga2d_vec_make(0, 0);
    c.radius = (ga2d_real)r;
    return ga2d_shape_create_circle(a->world, body, sd, &c);
}

/* A ball of radius r at (x, y) moving at v, with the shape def sd. */
static ga2d_shape_id add_ball(app *a, double x, double y, double r, ga2d_vec v, const ga2d_shape_def *sd)
{
    return add_circle(a, add_body(a, GA2D_BODY_DYNAMIC, x, y, 0, v), r, sd);
}

/* Scene 7: one body of the pile, of kind k (circle, capsule, box, rounded
   box, rounded hexagon), dropped across the top of the bin. */
static void pour_one(app *a, int k, int column)
{
    ga2d_shape_def sd = ga2d_default_shape_def();
    double x = -BIN_HALF_W + (column + 0.5) * (2 * BIN_HALF_W / 6) + 0.4 * (app_random(a) - 0.5);
    double y = 13 + 0.3 * app_random(a);
    double angle = PI_D * app_random(a);
    double size = app_random(a);
    ga2d_body_id id = add_body(a, GA2D_BODY_DYNAMIC, x, y, angle, ga2d_vec_make(0, 0));
    if (k == 0) add_circle(a, id, 0.25 + 0.2 * size, &sd);
    else if (k == 1) {
        ga2d_capsule c;
        double half = 0.25 + 0.3 * size;
        c.center1 = ga2d_vec_make((ga2d_real)-half, 0);
        c.center2 = ga2d_vec_make((ga2d_real)half, 0);
        c.radius = (ga2d_real)(0.18 + 0.07 * size);
        ga2d_shape_create_capsule(a->world, id, &sd, &c);
    } else {
        ga2d_polygon p;
        if (k == 2) p = ga2d_polygon_box((ga2d_real)(0.3 + 0.2 * size), (ga2d_real)(0.25 + 0.15 * size));
        else if (k == 3) p = ga2d_polygon_rounded_box((ga2d_real)(0.35 + 0.2 * size), (ga2d_real)(0.25 + 0.1 * size), 0.1f);
        else {
            p = ga2d_polygon_regular(6, (ga2d_real)(0.25 + 0.15 * size));
            p.radius = 0.08f;
        }
        ga2d_shape_create_polygon(a->world, id, &sd, &p);
    }
}

/* Scene 8: the half-pipe's outline (terrain.c's), counter-clockwise, so
   that the loop holds bodies inside it: a quarter pipe, 20 m flat, a
   cosine hill 1 m high, a cosine bowl 1.5 m deep, a second quarter pipe,
   the ceiling. */
static int halfpipe(ga2d_vec *pts, int cap)
{
    int n = 0, i;
    double x;
#define HP_ADD(px, py) do { if (n < cap) pts[n++] = ga2d_vec_make((ga2d_real)(px), (ga2d_real)(py)); } while (0)
    for (i = 0; i < 18; ++i) HP_ADD(-20 + 3 * cos(PI_D + i * PI_D / 36), 3 + 3 * sin(PI_D + i * PI_D / 36));
    for (x = -20; x < -1e-9; x += 0.5) HP_ADD(x, 0);
    for (i = 0; i < 128; ++i) HP_ADD(i / 16.0, (1 - cos(2 * PI_D * i / 128)) / 2);
    for (x = 8; x < 10 - 1e-9; x += 0.5) HP_ADD(x, 0);
    for (i = 0; i < 160; ++i) HP_ADD(10 + i / 16.0, -1.5 * (1 - cos(2 * PI_D * i / 160)) / 2);
    for (x = 20; x < 22 - 1e-9; x += 0.5) HP_ADD(x, 0);
    for (i = 0; i <= 18; ++i) HP_ADD(22 + 3 * cos(1.5 * PI_D + i * PI_D / 36), 3 + 3 * sin(1.5 * PI_D + i * PI_D / 36));
    HP_ADD(25, 5);
    HP_ADD(-23, 5);
#undef HP_ADD
    return n;
}

/* Scene 10's pre-solve callback (the world def's, for every scene; only the
   platform's shape asks for it): a contact with the platform pushes only
   a body above it (the normal from the platform points up at it) that is
   not rising through it.  The world is locked: this only reads it. */
static int one_way_platform(ga2d_shape_id shape_a, ga2d_shape_id shape_b, const ga2d_manifold *m, void *ctx)
{
    const app *a = (const app *)ctx;
    double up;
    ga2d_shape_id other;
    if (ga2d_shape_id_equal(shape_a, a->platform)) {
        up = (double)m->normal.y;
        other = shape_b;
    } else if (ga2d_shape_id_equal(shape_b, a->platform)) {
        up = -(double)m->normal.y;
        other = shape_a;
    } else
        return 1;
    return up > 0.5 && (double)ga2d_body_velocity(a->world, ga2d_shape_body(a->world, other)).y < 0.5;
}

/* Builds scenes 6-10 (load_scene has made the world). */
static void load_shape_scene(app *a, int scene)
{
    ga2d_shape_def sd = ga2d_default_shape_def();
    switch (scene) {
    case 6: { /* roll.c: friction 1 on the slope, so the bodies' own are mu^2 */
        const double th = 20 * PI_D / 180;
        const ga2d_rotor q = ga2d_rotor_from_angle((ga2d_real)-th);
        const ga2d_vec c = ga2d_vec_make(0, 4);
        ga2d_polygon p = ga2d_polygon_box(10, 0.5f), unit = ga2d_polygon_box(0.5f, 0.5f);
        ga2d_vec at;
        ga2d_body_id slope;
        add_ground(a, 0.6f);
        slope = add_body(a, GA2D_BODY_STATIC, (double)c.x, (double)c.y, -th, ga2d_vec_make(0, 0));
        sd.friction = 1;
        ga2d_shape_create_polygon(a->world, slope, &sd, &p);
        at = ga2d_vec_add(c, ga2d_rotate(q, ga2d_vec_make(-8, 1))); /* the box, 0.3 */
        sd.friction = 0.09f;
        ga2d_shape_create_polygon(a->world, add_body(a, GA2D_BODY_DYNAMIC, (double)at.x, (double)at.y, -th, ga2d_vec_make(0, 0)),
                                  &sd, &unit);
        add_label(a, at.x, at.y + (ga2d_real)1.5, "BOX MU 0.3: SLIDES");
        at = ga2d_vec_add(c, ga2d_rotate(q, ga2d_vec_make(-4, 1))); /* the ball, 0.6 */
        sd.friction = 0.36f;
        add_circle(a, add_body(a, GA2D_BODY_DYNAMIC, (double)at.x, (double)at.y, -th, ga2d_vec_make(0, 0)), 0.5, &sd);
        add_label(a, at.x + 1, at.y + (ga2d_real)1.5, "BALL MU 0.6: ROLLS");
        a->cam = camera_fit(-11, -1.5, 16, 9);
        break;
    }
    case 7: /* pile.c: a bin, filled by scene_before_step */
        add_box(a, GA2D_BODY_STATIC, 0, -0.5f, (ga2d_real)(BIN_HALF_W + 1), 0.5f, 0, 0.6f, 0);
        add_box(a, GA2D_BODY_STATIC, (ga2d_real)(-BIN_HALF_W - 0.5), 5.5f, 0.5f, 5.5f, 0, 0.6f, 0);
        add_box(a, GA2D_BODY_STATIC, (ga2d_real)(BIN_HALF_W + 0.5), 5.5f, 0.5f, 5.5f, 0, 0.6f, 0);
        a->cam = camera_fit(-10, -1.5, 10, 14.5);
        break;
    case 8: { /* terrain.c: a frictionless box and a rolling ball, not meeting */
        static ga2d_vec pts[512];
        ga2d_chain_def cd = ga2d_default_chain_def();
        ga2d_polygon unit = ga2d_polygon_box(0.5f, 0.5f);
        ga2d_body_id ground = add_body(a, GA2D_BODY_STATIC, 0, 0, 0, ga2d_vec_make(0, 0));
        cd.points = pts;
        cd.count = halfpipe(pts, 512);
        cd.is_loop = 1;
        ga2d_chain_create(a->world, ground, &cd);
        sd.friction = 0;
        sd.filter.category_bits = 2;
        sd.filter.mask_bits = 1;
        ga2d_shape_create_polygon(a->world, add_body(a, GA2D_BODY_DYNAMIC, -18, 0.5, 0, ga2d_vec_make(5, 0)), &sd, &unit);
        sd.friction = 0.6f;
        sd.filter.category_bits = 4;
        {
            ga2d_body_id ball = add_body(a, GA2D_BODY_DYNAMIC, -15, 0.5, 0, ga2d_vec_make(5, 0));
            add_circle(a, ball, 0.5, &sd);
            ga2d_body_set_angular_velocity(a->world, ball, -10); /* rolling: w r = v */
        }
        add_label(a, -9, 3, "ONE LOOP CHAIN, 375 POINTS");
        a->cam = camera_fit(-24, -2, 26, 6);
        break;
    }
    case 9: { /* sensor.c: a static body whose one shape is an is_sensor box */
        ga2d_polygon zone = ga2d_polygon_box(6, (ga2d_real)((ZONE_TOP - ZONE_BOTTOM) / 2));
        ga2d_polygon unit = ga2d_polygon_box(0.3f, 0.3f);
        add_box(a, GA2D_BODY_STATIC, 0, -0.5f, 8, 0.5f, 0, 0.6f, 0);
        a->zone = add_body(a, GA2D_BODY_STATIC, 0, (ZONE_TOP + ZONE_BOTTOM) / 2, 0, ga2d_vec_make(0, 0));
        sd.is_sensor = 1;
        a->zone_shape = ga2d_shape_create_polygon(a->world, a->zone, &sd, &zone);
        sd = ga2d_default_shape_def();
        sd.enable_sensor_events = 0; /* a box the sensor never sees */
        ga2d_shape_create_polygon(a->world, add_body(a, GA2D_BODY_DYNAMIC, -3, ZONE_TOP + 1, 0, ga2d_vec_make(0, 0)), &sd, &unit);
        add_label(a, -3, 1.4f, "UNSEEN BOX");
        a->cam = camera_fit(-9, -1.5, 9, 11);
        break;
    }
    default: { /* 10, platform.c: a one-way platform, balls thrown up by scene_before_step */
        ga2d_polygon slab = ga2d_polygon_box(4, 0.1f);
        add_box(a, GA2D_BODY_STATIC, 0, -0.5f, 7, 0.5f, 0, 0.6f, 0);
        sd.enable_pre_solve_events = 1;
        a->platform = ga2d_shape_create_polygon(
            a->world, add_body(a, GA2D_BODY_STATIC, 0, PLATFORM_TOP - 0.1, 0, ga2d_vec_make(0, 0)), &sd, &slab);
        a->cam = camera_fit(-8, -1.5, 8, 8);
        break;
    }
    }
}

/* Scene 11 (J): examples/bridge.c's bridge (its joints braked by their
   motors, at speed 0) under three boxes, and a chain of capsule links
   hinged to a static point, a heavy ball at its end, let go level. */
#define BRIDGE_PLANKS 20
#define CHAIN_LINKS 12
static void load_joint_scene(app *a)
{
    ga2d_shape_def sd = ga2d_default_shape_def();
    ga2d_revolute_joint_def jd = ga2d_default_revolute_joint_def();
    ga2d_capsule link = {{-0.25f, 0}, {0.25f, 0}, 0.08f};
    ga2d_body_id prev, pivot;
    int i;
    add_ground(a, 0.6f);
    prev = add_box(a, GA2D_BODY_STATIC, -10.25f, 2.5f, 0.25f, 2.5f, 0, 0.6f, 0); /* the posts */
    jd.enable_motor = 1; /* joint friction: a motor at speed 0 with at most 5 N m */
    jd.max_motor_torque = 5;
    for (i = 0; i <= BRIDGE_PLANKS; ++i) {
        ga2d_vec p = ga2d_vec_make((ga2d_real)(-10 + i), 5);
        ga2d_body_id next = i < BRIDGE_PLANKS
                                ? add_box(a, GA2D_BODY_DYNAMIC, (ga2d_real)(-9.5 + i), 5, 0.5f, 0.125f, 0, 0.6f, 0)
                                : add_box(a, GA2D_BODY_STATIC, 10.25f, 2.5f, 0.25f, 2.5f, 0, 0.6f, 0);
        jd.body_a = prev;
        jd.body_b = next;
        jd.local_anchor_a = ga2d_body_local_point(a->world, prev, p);
        jd.local_anchor_b = ga2d_body_local_point(a->world, next, p);
        ga2d_revolute_joint_create(a->world, &jd);
        prev = next;
    }
    for (i = 0; i < 3; ++i) add_box(a, GA2D_BODY_DYNAMIC, (ga2d_real)(-4 + 4 * i), (ga2d_real)(8 + 2 * i), 0.5f, 0.5f, 0, 0.6f, 0);

    jd = ga2d_default_revolute_joint_def(); /* the chain: links 0.5 m apart, leftward from the pivot */
    pivot = prev = add_body(a, GA2D_BODY_STATIC, -13, 11, 0, ga2d_vec_make(0, 0));
    for (i = 0; i < CHAIN_LINKS; ++i) {
        ga2d_body_id next = add_body(a, GA2D_BODY_DYNAMIC, -13.25 - 0.5 * i, 11, 0, ga2d_vec_make(0, 0));
        ga2d_shape_create_capsule(a->world, next, &sd, &link);
        jd.body_a = prev;
        jd.body_b = next;
        jd.local_anchor_a = ga2d_body_id_equal(prev, pivot) ? ga2d_vec_make(0, 0) : ga2d_vec_make(-0.25f, 0);
        jd.local_anchor_b = ga2d_vec_make(0.25f, 0);
        ga2d_revolute_joint_create(a->world, &jd);
        prev = next;
    }
    sd.density = 20; /* the ball: 10 kg, 70 times a link */
    {
        ga2d_body_id ball = add_body(a, GA2D_BODY_DYNAMIC, -13 - 0.5 * CHAIN_LINKS - 0.4, 11, 0, ga2d_vec_make(0, 0));
        add_circle(a, ball, 0.4, &sd);
        jd.body_a = prev;
        jd.body_b = ball;
        jd.local_anchor_a = ga2d_vec_make(-0.25f, 0);
        jd.local_anchor_b = ga2d_vec_make(0.4f, 0);
        ga2d_revolute_joint_create(a->world, &jd);
    }
    add_label(a, 0, 9.8f, "BRIDGE: 21 REVOLUTE JOINTS");
    add_label(a, -13, 12.2f, "CHAIN");
    a->cam = camera_fit(-21, -1.5, 12, 12.5);
}

/* Scenes 7, 9 and 10 add bodies as they run: the pile's rows of six every
   0.15 s, a ball over the sensor every 0.5 s, a ball thrown up under the
   platform every 0.6 s. */
static void scene_before_step(app *a)
{
    ga2d_shape_def sd = ga2d_default_shape_def();
    int k = a->scene_steps++;
    if (a->scene == 7 && k % 9 == 0 && a->spawned < POUR_TOTAL) {
        int i;
        for (i = 0; i < 6 && a->spawned < POUR_TOTAL; ++i, ++a->spawned) pour_one(a, a->spawned % 5, i);
    } else if (a->scene == 9 && k % 30 == 0 && a->spawned < 40) {
        add_ball(a, -5.5 + 11 * app_random(a), ZONE_TOP + 1 + 3 * app_random(a), 0.25, ga2d_vec_make(0, 0), &sd);
        ++a->spawned;
    } else if (a->scene == 10 && k % 36 == 0 && a->spawned < 40) {
        static const double v0[4] = {6, 9, 10, 11};
        sd.enable_hit_events = 1;
        add_ball(a, -3.5 + (a->spawned % 8), 0.25, 0.25,
                 ga2d_vec_make((ga2d_real)(app_random(a) - 0.5), (ga2d_real)v0[a->spawned % 4]), &sd);
        ++a->spawned;
    }
}

/* After the step: the events and the status line. */
static void scene_after_step(app *a)
{
    double t = a->scene_steps * STEP_DT;
    int i;
    a->status[0] = '\0';
    if (a->scene == 6 && a->body_count >= 2) { /* on the slope: v against a t */
        double vb = (double)ga2d_vec_length(ga2d_body_velocity(a->world, a->bodies[0]));
        double vr = (double)ga2d_vec_length(ga2d_body_velocity(a->world, a->bodies[1]));
        const double s = sin(20 * PI_D / 180), c = cos(20 * PI_D / 180);
        if (ga2d_body_center(a->world, a->bodies[1]).x < 8)
            snprintf(a->status, sizeof a->status, "T %.2f S   BALL V %.3f (2/3 G SIN T %.3f)   BOX V %.3f (G(SIN - 0.3 COS) T %.3f)",
                     t, vr, 2.0 / 3.0 * 10 * s * t, vb, 10 * (s - 0.3 * c) * t);
    } else if (a->scene == 7) {
        int asleep = 0;
        for (i = 0; i < a->body_count; ++i) asleep += !ga2d_body_is_awake(a->world, a->bodies[i]);
        snprintf(a->status, sizeof a->status, "POURED %d OF %d   ASLEEP %d", a->spawned, POUR_TOTAL, asleep);
    } else if (a->scene == 8 && a->body_count >= 2) {
        snprintf(a->status, sizeof a->status, "BOX (NO FRICTION) V %.3f M/S   BALL (ROLLING) V %.3f M/S",
                 (double)ga2d_vec_length(ga2d_body_velocity(a->world, a->bodies[0])),
                 (double)ga2d_vec_length(ga2d_body_velocity(a->world, a->bodies[1])));
    } else if (a->scene == 9) {
        ga2d_sensor_events ev = ga2d_world_sensor_events(a->world);
        ga2d_shape_id held[64];
        int n = ga2d_shape_get_sensor_overlaps(a->world, a->zone_shape, held, 64);
        a->entered += ev.begin_count;
        a->left += ev.end_count;
        a->inside_count = n < 64 ? n : 64;
        for (i = 0; i < a->inside_count; ++i) a->inside[i] = ga2d_shape_body(a->world, held[i]);
        snprintf(a->status, sizeof a->status, "SENSOR: IN THE ZONE %d   BEGIN EVENTS %d   END EVENTS %d", n, a->entered,
                 a->left);
    } else if (a->scene == 10) {
        ga2d_contact_events ev = ga2d_world_contact_events(a->world);
        for (i = 0; i < ev.hit_count; ++i) {
            ++a->hits;
            a->last_hit = (double)ev.hit[i].approach_speed;
            a->last_hit_on_platform = ga2d_shape_id_equal(ev.hit[i].shape_a, a->platform) ||
                                      ga2d_shape_id_equal(ev.hit[i].shape_b, a->platform);
        }
        if (a->hits > 0)
            snprintf(a->status, sizeof a->status, "HIT EVENTS %d   LAST: %.2f M/S ON THE %s", a->hits, a->last_hit,
                     a->last_hit_on_platform ? "PLATFORM" : "GROUND");
    } else if (a->scene == 11) {
        ga2d_world_counters wc = ga2d_world_get_counters(a->world);
        snprintf(a->status, sizeof a->status, "JOINTS %d   SOLVED IN THE LAST STEP %d (NONE WHEN ASLEEP)", wc.joint_count,
                 wc.joints_solved);
    }
}

/* The colour a body is drawn in: blue while the sensor holds it. */
static uint32_t body_color(const app *a, ga2d_body_id id, uint32_t color)
{
    int i;
    for (i = 0; a->scene == 9 && i < a->inside_count; ++i)
        if (ga2d_body_id_equal(id, a->inside[i])) return INSIDE_COLOR;
    return color;
}

static void load_scene(app *a, int scene)
{
    ga2d_world_def wd = ga2d_default_world_def();
    int i, j;
    if (a->world) ga2d_world_destroy(a->world);
    wd.substeps = SUBSTEP_CHOICES[a->substep_index];
    wd.solver = a->solver;
    wd.enable_sleep = a->sleep_on;
    wd.pre_solve = one_way_platform; /* asked only about the platform's contacts (scene 10) */
    wd.pre_solve_context = a;
    a->world = ga2d_world_create(&wd);
    if (!a->world) {
        fprintf(stderr, "sdl_demo: ga2d_world_create failed\n");
        exit(1);
    }
    a->scene = scene;
    a->body_count = a->label_count = 0;
    a->dragging = a->aiming = 0;
    a->step_ms_count = a->step_ms_next = 0;
    a->status[0] = '\0';
    a->scene_steps = a->spawned = a->inside_count = a->entered = a->left = a->hits = 0;
    a->rng = 12345u;
    a->zone = ga2d_body_id_null();
    a->zone_shape = a->platform = ga2d_shape_id_null();

    switch (scene) {
    case 1: /* Box2D's pyramid: row i holds boxes j = i..19 */
        add_ground(a, 0.6f);
        for (i = 0; i < 20; ++i)
            for (j = i; j < 20; ++j)
                add_box(a, GA2D_BODY_DYNAMIC, (ga2d_real)((i + 1) * 0.5 + (j - i) - 10.0),
                        (ga2d_real)((2 * i + 1) * 0.5), 0.5f, 0.5f, 0, 0.6f, 0);
        a->cam = camera_fit(-13, -1.5, 13, 23);
        break;
    case 2: /* ten 1 m boxes, one on another */
        add_ground(a, 0.6f);
        for (i = 0; i < 10; ++i) add_box(a, GA2D_BODY_DYNAMIC, 0, (ga2d_real)(0.5 + i), 0.5f, 0.5f, 0, 0.6f, 0);
        a->cam = camera_fit(-9, -1.5, 9, 12);
        break;
    case 3: { /* a striker into a row of four, on frictionless ground between
                 two walls: everything has e = 1, so it goes on and on */
        ga2d_body_id striker;
        add_ground(a, 0);
        add_box(a, GA2D_BODY_STATIC, -10, 2, 0.5f, 2, 0, 0, 1);
        add_box(a, GA2D_BODY_STATIC, 10, 2, 0.5f, 2, 0, 0, 1);
        for (i = 0; i < 4; ++i) add_box(a, GA2D_BODY_DYNAMIC, (ga2d_real)i, 0.5f, 0.5f, 0.5f, 0, 0, 1);
        striker = add_box(a, GA2D_BODY_DYNAMIC, -5, 0.5f, 0.5f, 0.5f, 0, 0, 1);
        ga2d_body_set_velocity(a->world, striker, ga2d_vec_make(6, 0));
        add_label(a, 1.5f, 5.0f, "E = 1, FRICTIONLESS");
        a->cam = camera_fit(-11, -1.5, 11, 6);
        break;
    }
    case 4: { /* three ramps at 25 degrees (tan = 0.47), each with a box; the
                 ramps have friction 1, so sqrt(mu_box * 1) is the mix */
        const ga2d_real theta = (ga2d_real)(25.0 * PI_D / 180.0);
        const ga2d_real box_mu[3] = {0.01f, 0.16f, 0.64f};
        const char *const names[3] = {"MU 0.1: SLIDES", "MU 0.4: CREEPS", "MU 0.8: STICKS"};
        ga2d_vec t = ga2d_vec_make((ga2d_real)cos((double)theta), -(ga2d_real)sin((double)theta)); /* downhill */
        ga2d_vec n = ga2d_vec_perp(t);                                                         /* up, out */
        add_ground(a, 0.6f);
        for (i = 0; i < 3; ++i) {
            ga2d_vec c = ga2d_vec_make((ga2d_real)(-13 + 13 * i), 4);
            ga2d_vec b = ga2d_vec_add(c, ga2d_vec_add(ga2d_vec_scale(n, 0.76f), ga2d_vec_scale(t, -3.5f)));
            add_box(a, GA2D_BODY_STATIC, c.x, c.y, 5, 0.25f, -theta, 1, 0);
            add_box(a, GA2D_BODY_DYNAMIC, b.x, b.y, 0.5f, 0.5f, -theta, box_mu[i], 0);
            add_label(a, c.x, 7.6f, names[i]);
        }
        a->cam = camera_fit(-19, -1.5, 19, 8.5);
        break;
    }
    case 5: /* three boxes dropped side by side */
    {
        const ga2d_real e[3] = {0.3f, 0.6f, 0.9f};
        const char *const names[3] = {"E 0.3", "E 0.6", "E 0.9"};
        add_ground(a, 0.6f);
        for (i = 0; i < 3; ++i) {
            add_box(a, GA2D_BODY_DYNAMIC, (ga2d_real)(-4 + 4 * i), 8, 0.5f, 0.5f, 0, 0.6f, e[i]);
            add_label(a, (ga2d_real)(-4 + 4 * i), 9.6f, names[i]);
        }
        a->cam = camera_fit(-8, -1.5, 8, 10.5);
        break;
    }
    case 11: load_joint_scene(a); break;
    default: load_shape_scene(a, scene); break;
    }
}

/* ------------------------------------------------------------------ picking */
typedef struct pick_query { const app *a; ga2d_vec p; ga2d_body_id hit; } pick_query;

/* The distance from p to the segment a-b. */
static double segment_distance(ga2d_vec p, ga2d_vec a, ga2d_vec b)
{
    ga2d_vec ab = ga2d_vec_sub(b, a), ap = ga2d_vec_sub(p, a);
    double len2 = (double)ga2d_vec_length_sq(ab), t = len2 > 0 ? (double)ga2d_dot(ap, ab) / len2 : 0;
    if (t < 0) t = 0;
    if (t > 1) t = 1;
    return (double)ga2d_vec_length(ga2d_vec_sub(ap, ga2d_vec_scale(ab, (ga2d_real)t)));
}

/* Called by ga2d_world_draw for every shape in drawing order, so the last
   dynamic body whose shape holds the point is the one drawn on top.  A
   polygon holds it when it is inside, or within the polygon's radius of
   an edge. */
static void pick_polygon(ga2d_body_id id, const ga2d_polygon *poly, ga2d_transform x, uint32_t color, void *ctx)
{
    pick_query *q = (pick_query *)ctx;
    ga2d_vec local = ga2d_transform_apply_inv(x, q->p);
    int i, inside = 1;
    double nearest = 1e30;
    (void)color;
    if (ga2d_body_get_type(q->a->world, id) != GA2D_BODY_DYNAMIC) return;
    for (i = 0; i < poly->count; ++i) {
        double d = segment_distance(local, poly->vertices[i], poly->vertices[(i + 1) % poly->count]);
        if (ga2d_dot(poly->normals[i], ga2d_vec_sub(local, poly->vertices[i])) > 0) inside = 0;
        if (d < nearest) nearest = d;
    }
    if (inside || nearest <= (double)poly->radius) q->hit = id;
}

static void pick_circle(ga2d_body_id id, ga2d_vec center, ga2d_real radius, ga2d_vec axis, uint32_t color, void *ctx)
{
    pick_query *q = (pick_query *)ctx;
    (void)axis;
    (void)color;
    if (ga2d_body_get_type(q->a->world, id) == GA2D_BODY_DYNAMIC &&
        ga2d_vec_length(ga2d_vec_sub(q->p, center)) <= radius)
        q->hit = id;
}

static void pick_capsule(ga2d_body_id id, ga2d_vec c1, ga2d_vec c2, ga2d_real radius, uint32_t color, void *ctx)
{
    pick_query *q = (pick_query *)ctx;
    (void)color;
    if (ga2d_body_get_type(q->a->world, id) == GA2D_BODY_DYNAMIC && segment_distance(q->p, c1, c2) <= (double)radius)
        q->hit = id;
}

static ga2d_body_id pick_body(const app *a, ga2d_vec p)
{
    pick_query q;
    ga2d_debug_draw dd = ga2d_default_debug_draw();
    q.a = a;
    q.p = p;
    q.hit = ga2d_body_id_null();
    dd.polygon = pick_polygon;
    dd.circle = pick_circle;
    dd.capsule = pick_capsule;
    dd.context = &q;
    ga2d_world_draw(a->world, &dd);
    return q.hit;
}

/* Grab the body under world point p: a static body with no shape is
   made there, and a motor joint from it to the grabbed point, whose
   target (linear_offset, from the static body's anchor) apply_drag moves
   to the cursor.  Its force is capped at DRAG_WEIGHTS times the body's
   weight, so a drag lifts what it holds but cannot fling it through the
   scene; its torque at DRAG_SPIN times the inertia, with the angle target
   kept at the body's own angle: a brake on spin only. */
static void start_drag(app *a, ga2d_vec p)
{
    ga2d_body_def bd = ga2d_default_body_def(); /* static, no shape */
    ga2d_motor_joint_def jd = ga2d_default_motor_joint_def();
    ga2d_body_id id = pick_body(a, p);
    ga2d_mass md;
    if (ga2d_body_id_is_null(id)) return;
    md = ga2d_body_mass_data(a->world, id);
    bd.position = p;
    a->mouse = ga2d_body_create(a->world, &bd);
    jd.body_a = a->mouse;
    jd.body_b = id;
    jd.local_anchor_b = ga2d_body_local_point(a->world, id, p); /* A's anchor: its origin, p */
    jd.angular_offset = ga2d_body_angle(a->world, id);
    jd.max_force = (ga2d_real)(DRAG_WEIGHTS * (double)md.mass * (double)ga2d_vec_length(ga2d_world_gravity(a->world)));
    jd.max_torque = (ga2d_real)(DRAG_SPIN * (double)md.inertia);
    a->drag = ga2d_motor_joint_create(a->world, &jd); /* wakes the body */
    if (ga2d_joint_id_is_null(a->drag)) {
        ga2d_body_destroy(a->world, a->mouse);
        return;
    }
    a->grab = id;
    a->grab_local = jd.local_anchor_b;
    a->dragging = 1;
}

/* On release (or when the grabbed body is gone): the joint, then its
   static body.  (Destroying the body alone would take the joint with it.) */
static void end_drag(app *a)
{
    if (!a->dragging) return;
    a->dragging = 0;
    ga2d_joint_destroy(a->world, a->drag); /* STALE_ID if the grabbed body was destroyed: fine */
    ga2d_body_destroy(a->world, a->mouse);
}

/* Before every step: the joint's target to the cursor, its angle target
   to the body's angle (so the torque only brakes spin). */
static void apply_drag(app *a)
{
    if (!a->dragging) return;
    if (!ga2d_joint_is_valid(a->world, a->drag)) {
        end_drag(a);
        return;
    }
    ga2d_motor_joint_set_linear_offset(a->world, a->drag, ga2d_vec_sub(a->cursor, ga2d_body_position(a->world, a->mouse)));
    ga2d_motor_joint_set_angular_offset(a->world, a->drag, ga2d_body_angle(a->world, a->grab));
}

/* A new 1 m box at p with velocity v. */
static void throw_box(app *a, ga2d_vec p, ga2d_vec v)
{
    ga2d_body_id id;
    if (a->body_count >= MAX_BODIES) return;
    id = add_box(a, GA2D_BODY_DYNAMIC, p.x, p.y, 0.5f, 0.5f, 0, 0.6f, 0.1f);
    if (!ga2d_body_id_is_null(id)) ga2d_body_set_velocity(a->world, id, v);
}

/* The throw's velocity: 4 /s times the drag (press to release), at most
   30 m/s; a click without a drag throws up and to the right. */
static ga2d_vec throw_velocity(ga2d_vec from, ga2d_vec to)
{
    ga2d_vec d = ga2d_vec_scale(ga2d_vec_sub(to, from), 4);
    ga2d_real len = ga2d_vec_length(d);
    if (len < 1) return ga2d_vec_make(10, 5);
    if (len > 30) d = ga2d_vec_scale(d, 30 / len);
    return d;
}

/* Bodies that fell off the ground are removed. */
static void cull_fallen(app *a)
{
    int i, kept = 0;
    for (i = 0; i < a->body_count; ++i) {
        ga2d_body_id id = a->bodies[i];
        if (!ga2d_body_is_valid(a->world, id)) continue;
        if (ga2d_body_center(a->world, id).y < -40) {
            if (a->dragging && ga2d_body_id_equal(id, a->grab)) end_drag(a);
            ga2d_body_destroy(a->world, id);
            continue;
        }
        a->bodies[kept++] = id;
    }
    a->body_count = kept;
}

static void step_world(app *a)
{
    Uint64 t0, t1;
    scene_before_step(a);
    apply_drag(a);
    t0 = SDL_GetPerformanceCounter();
    ga2d_world_step(a->world, (ga2d_real)STEP_DT);
    t1 = SDL_GetPerformanceCounter();
    scene_after_step(a);
    a->step_ms[a->step_ms_next] = 1000.0 * (double)(t1 - t0) / (double)SDL_GetPerformanceFrequency();
    a->step_ms_next = (a->step_ms_next + 1) % TIMING_WINDOW;
    if (a->step_ms_count < TIMING_WINDOW) ++a->step_ms_count;
    cull_fallen(a);
}

static double average_step_ms(const app *a)
{
    double sum = 0;
    int i;
    for (i = 0; i < a->step_ms_count; ++i) sum += a->step_ms[i];
    return a->step_ms_count ? sum / a->step_ms_count : 0;
}

/* ---------------------------------------------------------------- drawing */
static SDL_Color rgb(uint32_t c, double k)
{
    SDL_Color s;
    s.r = (Uint8)((double)((c >> 16) & 0xFF) * k);
    s.g = (Uint8)((double)((c >> 8) & 0xFF) * k);
    s.b = (Uint8)((double)(c & 0xFF) * k);
    s.a = 255;
    return s;
}

/* Round outlines as convex polygons: a circle in ROUND_POINTS points, a
   rounded polygon's corner in CORNER_POINTS. */
#define ROUND_POINTS 32
#define CORNER_POINTS 6
#define MAX_OUTLINE (GA2D_MAX_POLYGON_VERTICES * CORNER_POINTS + ROUND_POINTS + 2)

/* A convex outline (world points, counter-clockwise): a filled fan of
   triangles in a darker shade of its colour (see-through at alpha < 255),
   then its edge in the colour itself, or in white while dragged. */
static void draw_convex(const app *a, const ga2d_vec *pts, int n, uint32_t color, int grabbed, Uint8 alpha)
{
    SDL_Vertex v[MAX_OUTLINE];
    SDL_FPoint line[MAX_OUTLINE + 1];
    int idx[3 * MAX_OUTLINE];
    int i, ni = 0;
    SDL_Color fill = rgb(color, 0.55), edge = grabbed ? rgb(0xFFFFFFu, 1) : rgb(color, 1);
    if (n < 3 || n > MAX_OUTLINE) return;
    fill.a = alpha;
    for (i = 0; i < n; ++i) {
        v[i].position = line[i] = to_screen(&a->cam, pts[i]);
        v[i].color = fill;
        v[i].tex_coord.x = v[i].tex_coord.y = 0;
    }
    line[n] = line[0];
    for (i = 1; i + 1 < n; ++i) {
        idx[ni++] = 0;
        idx[ni++] = i;
        idx[ni++] = i + 1;
    }
    if (alpha < 255) SDL_SetRenderDrawBlendMode(a->ren, SDL_BLENDMODE_BLEND);
    SDL_RenderGeometry(a->ren, NULL, v, n, idx, ni);
    SDL_SetRenderDrawBlendMode(a->ren, SDL_BLENDMODE_NONE);
    SDL_SetRenderDrawColor(a->ren, edge.r, edge.g, edge.b, 255);
    SDL_RenderDrawLinesF(a->ren, line, n + 1);
}

/* Appends to pts the arc of radius r about c from angle a0, turning
   counter-clockwise by da, in m points (both ends included). */
static int arc_points(ga2d_vec *pts, int n, ga2d_vec c, double r, double a0, double da, int m)
{
    int i;
    for (i = 0; i < m && n < MAX_OUTLINE; ++i) {
        double t = a0 + da * i / (m - 1);
        pts[n++] = ga2d_vec_make((ga2d_real)((double)c.x + r * cos(t)), (ga2d_real)((double)c.y + r * sin(t)));
    }
    return n;
}

static int is_grabbed(const app *a, ga2d_body_id id) { return a->dragging && ga2d_body_id_equal(id, a->grab); }

/* A polygon; a rounded one (radius > 0) with an arc at each corner, from
   the normal of the edge before it to the normal of the edge after it.
   The sensor zone is see-through. */
static void draw_polygon(ga2d_body_id id, const ga2d_polygon *p, ga2d_transform x, uint32_t color, void *ctx)
{
    const app *a = (const app *)ctx;
    ga2d_vec pts[MAX_OUTLINE];
    int i, n = 0;
    double r = (double)p->radius;
    if (p->count < 3 || p->count > GA2D_MAX_POLYGON_VERTICES) return;
    for (i = 0; i < p->count; ++i) {
        ga2d_vec v = ga2d_transform_apply(x, p->vertices[i]);
        if (r > 0) {
            ga2d_vec n0 = ga2d_rotate(x.q, p->normals[(i + p->count - 1) % p->count]), n1 = ga2d_rotate(x.q, p->normals[i]);
            double a0 = atan2((double)n0.y, (double)n0.x), da = atan2((double)n1.y, (double)n1.x) - a0;
            while (da < 0) da += 2 * PI_D;
            n = arc_points(pts, n, v, r, a0, da, CORNER_POINTS);
        } else
            pts[n++] = v;
    }
    draw_convex(a, pts, n, body_color(a, id, color), is_grabbed(a, id), ga2d_body_id_equal(id, a->zone) ? 60 : 255);
}

/* A circle, and a line from its centre along the body's x axis (it shows
   the circle turn as it rolls). */
static void draw_circle(ga2d_body_id id, ga2d_vec center, ga2d_real radius, ga2d_vec axis, uint32_t color, void *ctx)
{
    const app *a = (const app *)ctx;
    ga2d_vec pts[ROUND_POINTS];
    SDL_FPoint c = to_screen(&a->cam, center), e = to_screen(&a->cam, ga2d_vec_add(center, ga2d_vec_scale(axis, radius)));
    SDL_Color edge = rgb(body_color(a, id, color), 1);
    int n = arc_points(pts, 0, center, (double)radius, 0, 2 * PI_D * (ROUND_POINTS - 1) / ROUND_POINTS, ROUND_POINTS);
    draw_convex(a, pts, n, body_color(a, id, color), is_grabbed(a, id), 255);
    SDL_SetRenderDrawColor(a->ren, edge.r, edge.g, edge.b, 255);
    SDL_RenderDrawLineF(a->ren, c.x, c.y, e.x, e.y);
}

/* A capsule: half a circle round each end, joined by the two sides. */
static void draw_capsule(ga2d_body_id id, ga2d_vec c1, ga2d_vec c2, ga2d_real radius, uint32_t color, void *ctx)
{
    const app *a = (const app *)ctx;
    ga2d_vec pts[ROUND_POINTS + 2];
    double base = atan2((double)(c2.y - c1.y), (double)(c2.x - c1.x));
    int n = arc_points(pts, 0, c2, (double)radius, base - PI_D / 2, PI_D, ROUND_POINTS / 2 + 1);
    n = arc_points(pts, n, c1, (double)radius, base + PI_D / 2, PI_D, ROUND_POINTS / 2 + 1);
    draw_convex(a, pts, n, body_color(a, id, color), is_grabbed(a, id), 255);
}

/* A segment (the chain's): a line two pixels wide. */
static void draw_segment(ga2d_vec p, ga2d_vec q, uint32_t color, void *ctx)
{
    const app *a = (const app *)ctx;
    SDL_FPoint s = to_screen(&a->cam, p), e = to_screen(&a->cam, q);
    SDL_Color c = rgb(color, 1);
    SDL_SetRenderDrawColor(a->ren, c.r, c.g, c.b, 255);
    SDL_RenderDrawLineF(a->ren, s.x, s.y, e.x, e.y);
    SDL_RenderDrawLineF(a->ren, s.x, s.y + 1, e.x, e.y + 1);
}

/* A contact point: a small square and its normal, 0.3 m long. */
static void draw_contact(ga2d_vec p, ga2d_vec normal, ga2d_real separation, uint32_t color, void *ctx)
{
    const app *a = (const app *)ctx;
    SDL_Color c = rgb(color, 1);
    SDL_FPoint s = to_screen(&a->cam, p), e = to_screen(&a->cam, ga2d_vec_add(p, ga2d_vec_scale(normal, 0.3f)));
    SDL_FRect r;
    (void)separation;
    r.x = s.x - 3;
    r.y = s.y - 3;
    r.w = r.h = 6;
    SDL_SetRenderDrawColor(a->ren, c.r, c.g, c.b, 255);
    SDL_RenderFillRectF(a->ren, &r);
    SDL_SetRenderDrawColor(a->ren, 255, 230, 120, 255);
    SDL_RenderDrawLineF(a->ren, s.x, s.y, e.x, e.y);
}

static void draw_dot(SDL_Renderer *r, SDL_FPoint p, float half)
{
    SDL_FRect q;
    q.x = p.x - half;
    q.y = p.y - half;
    q.w = q.h = 2 * half;
    SDL_RenderFillRectF(r, &q);
}

static void draw_frame(app *a)
{
    SDL_Renderer *r = a->ren;
    ga2d_debug_draw dd = ga2d_default_debug_draw();
    ga2d_world_counters wc = ga2d_world_get_counters(a->world);
    SDL_Color white = {235, 235, 235, 255}, dim = {150, 160, 175, 255}, yellow = {255, 220, 110, 255};
    SDL_Rect panel;
    char line[160];
    int i;

    SDL_SetRenderDrawColor(r, 24, 26, 32, 255);
    SDL_RenderClear(r);

    dd.polygon = draw_polygon;
    dd.circle = draw_circle;
    dd.capsule = draw_capsule;
    dd.segment = draw_segment;
    dd.contact = draw_contact;
    dd.draw_contacts = a->show_contacts;
    dd.context = a;
    ga2d_world_draw(a->world, &dd);

    for (i = 0; i < a->label_count; ++i) {
        SDL_FPoint s = to_screen(&a->cam, a->labels[i].at);
        draw_text_shadowed(r, (int)s.x - text_width(a->labels[i].text, 2) / 2, (int)s.y, 2, a->labels[i].text, yellow);
    }

    if (a->dragging) { /* the drag: grab point to cursor */
        ga2d_vec gp = ga2d_transform_apply(ga2d_body_transform(a->world, a->grab), a->grab_local);
        SDL_FPoint s = to_screen(&a->cam, gp), e = to_screen(&a->cam, a->cursor);
        SDL_SetRenderDrawColor(r, 255, 255, 255, 255);
        SDL_RenderDrawLineF(r, s.x, s.y, e.x, e.y);
        draw_dot(r, s, 3);
        SDL_SetRenderDrawColor(r, 120, 220, 255, 255);
        draw_dot(r, e, 4);
    }
    if (a->aiming) { /* the throw: where the box starts, and its velocity / 4 */
        SDL_FPoint s = to_screen(&a->cam, a->aim_from), e = to_screen(&a->cam, a->cursor);
        SDL_SetRenderDrawColor(r, 120, 220, 255, 255);
        SDL_RenderDrawLineF(r, s.x, s.y, e.x, e.y);
        draw_dot(r, s, 4);
    }

    /* text panels */
    SDL_SetRenderDrawBlendMode(r, SDL_BLENDMODE_BLEND);
    SDL_SetRenderDrawColor(r, 0, 0, 0, 170);
    panel.x = 0;
    panel.y = 0;
    panel.w = WINDOW_W;
    panel.h = HUD_TOP - 6;
    SDL_RenderFillRect(r, &panel);
    panel.y = WINDOW_H - HUD_BOTTOM;
    panel.h = HUD_BOTTOM;
    SDL_RenderFillRect(r, &panel);
    SDL_SetRenderDrawBlendMode(r, SDL_BLENDMODE_NONE);

    snprintf(line, sizeof line, "%d %s   BODIES %d   AWAKE %d   CONTACTS %d   STEP %.3f MS (AVG OF %d)%s",
             a->scene, SCENE_NAMES[a->scene], wc.body_count, wc.awake_body_count, wc.touching_count,
             average_step_ms(a), a->step_ms_count, a->paused ? "   PAUSED" : "");
    draw_text(r, 10, 8, 2, line, white);
    snprintf(line, sizeof line, "SUBSTEPS %d [S]   SOLVER %s [V]   SLEEP %s [Z]   CONTACT POINTS %s [C]",
             SUBSTEP_CHOICES[a->substep_index], SOLVER_NAMES[a->solver], a->sleep_on ? "ON" : "OFF",
             a->show_contacts ? "ON" : "OFF");
    draw_text(r, 10, 32, 2, line, white);
    if (a->status[0]) draw_text_shadowed(r, 10, HUD_TOP + 4, 2, a->status, yellow);
    draw_text(r, 10, WINDOW_H - HUD_BOTTOM + 8, 2,
              "1-9, 0, J SCENE  R RESET  LEFT DRAG: PULL  RIGHT DRAG: THROW A BOX  P PAUSE  ESC QUIT", dim);
}

/* Saves what the renderer drew (before SDL_RenderPresent) as a BMP. */
static int save_screenshot(SDL_Renderer *r, const char *path)
{
    int w, h, ok;
    SDL_Surface *s;
    if (SDL_GetRendererOutputSize(r, &w, &h) != 0) return 0;
    s = SDL_CreateRGBSurfaceWithFormat(0, w, h, 32, SDL_PIXELFORMAT_ARGB8888);
    if (!s) return 0;
    ok = SDL_RenderReadPixels(r, NULL, SDL_PIXELFORMAT_ARGB8888, s->pixels, s->pitch) == 0 &&
         SDL_SaveBMP(s, path) == 0;
    SDL_FreeSurface(s);
    return ok;
}

/* ------------------------------------------------------------------- input */
static void on_key(app *a, SDL_Keycode k, int *running)
{
    if (k >= SDLK_1 && k <= SDLK_9) load_scene(a, (int)(k - SDLK_0));
    if (k == SDLK_0) load_scene(a, 10);
    if (k == SDLK_j) load_scene(a, 11);
    switch (k) {
    case SDLK_ESCAPE: *running = 0; break;
    case SDLK_r: load_scene(a, a->scene); break;
    case SDLK_p: a->paused = !a->paused; break;
    case SDLK_c: a->show_contacts = !a->show_contacts; break;
    case SDLK_s:
        a->substep_index = (a->substep_index + 1) % 4;
        ga2d_world_set_substeps(a->world, SUBSTEP_CHOICES[a->substep_index]);
        a->step_ms_count = a->step_ms_next = 0;
        break;
    case SDLK_v:
        a->solver = (ga2d_solver)((a->solver + 1) % GA2D_SOLVER_COUNT);
        ga2d_world_set_solver(a->world, a->solver);
        a->step_ms_count = a->step_ms_next = 0;
        break;
    case SDLK_z:
        a->sleep_on = !a->sleep_on;
        ga2d_world_enable_sleep(a->world, a->sleep_on);
        a->step_ms_count = a->step_ms_next = 0;
        break;
    default: break;
    }
}

static void on_event(app *a, const SDL_Event *e, int *running)
{
    switch (e->type) {
    case SDL_QUIT: *running = 0; break;
    case SDL_KEYDOWN:
        if (!e->key.repeat) on_key(a, e->key.keysym.sym, running);
        break;
    case SDL_MOUSEMOTION: a->cursor = to_world(&a->cam, e->motion.x, e->motion.y); break;
    case SDL_MOUSEBUTTONDOWN:
        a->cursor = to_world(&a->cam, e->button.x, e->button.y);
        if (e->button.button == SDL_BUTTON_LEFT) start_drag(a, a->cursor);
        if (e->button.button == SDL_BUTTON_RIGHT) {
            a->aiming = 1;
            a->aim_from = a->cursor;
        }
        break;
    case SDL_MOUSEBUTTONUP:
        a->cursor = to_world(&a->cam, e->button.x, e->button.y);
        if (e->button.button == SDL_BUTTON_LEFT) end_drag(a);
        if (e->button.button == SDL_BUTTON_RIGHT && a->aiming) {
            a->aiming = 0;
            throw_box(a, a->aim_from, throw_velocity(a->aim_from, a->cursor));
        }
        break;
    default: break;
    }
}

/* --drag-test: the dynamic body whose centre is highest. */
static ga2d_body_id top_body(const app *a)
{
    ga2d_body_id best = ga2d_body_id_null();
    ga2d_real y = -1e30f;
    int i;
    for (i = 0; i < a->body_count; ++i) {
        ga2d_vec c = ga2d_body_center(a->world, a->bodies[i]);
        if (ga2d_body_is_valid(a->world, a->bodies[i]) && c.y > y) {
            y = c.y;
            best = a->bodies[i];
        }
    }
    return best;
}

/* Sends a synthetic mouse event through the same handler as real input. */
static void fake_mouse(app *a, Uint32 type, Uint8 button, ga2d_vec world, int *running)
{
    SDL_Event e;
    SDL_FPoint s = to_screen(&a->cam, world);
    memset(&e, 0, sizeof e);
    e.type = type;
    if (type == SDL_MOUSEMOTION) {
        e.motion.x = (Sint32)lround((double)s.x);
        e.motion.y = (Sint32)lround((double)s.y);
    } else {
        e.button.button = button;
        e.button.x = (Sint32)lround((double)s.x);
        e.button.y = (Sint32)lround((double)s.y);
    }
    on_event(a, &e, running);
}

static int usage(void)
{
    fprintf(stderr, "usage: sdl_demo [--scene 1-11] [--frames N] [--screenshot FILE.bmp] [--drag-test]\n"
                    "                [--throw-test] [--substeps 1|2|4|8] [--solver soft|baumgarte|ngs]\n"
                    "                [--no-sleep] [--contacts]\n");
    return 2;
}

int main(int argc, char *argv[])
{
    static app a; /* large (the body list): not on the stack */
    SDL_Window *window;
    const char *screenshot = NULL;
    int frames = 0, drag_test = 0, throw_test = 0, scene = 1, running = 1, frame, i;
    ga2d_vec drag_from = ga2d_vec_make(0, 0);
    Uint64 last;
    double accumulator = 0;

    a.substep_index = 2; /* 4, the library's default */
    a.solver = GA2D_SOLVER_SOFT_STEP;
    a.sleep_on = 1;
    for (i = 1; i < argc; ++i) {
        const char *o = argv[i], *val = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(o, "--scene") && val) scene = atoi(argv[++i]);
        else if (!strcmp(o, "--frames") && val) frames = atoi(argv[++i]);
        else if (!strcmp(o, "--screenshot") && val) screenshot = argv[++i];
        else if (!strcmp(o, "--drag-test")) drag_test = 1;
        else if (!strcmp(o, "--throw-test")) throw_test = 1;
        else if (!strcmp(o, "--no-sleep")) a.sleep_on = 0;
        else if (!strcmp(o, "--contacts")) a.show_contacts = 1;
        else if (!strcmp(o, "--substeps") && val) {
            int s = atoi(argv[++i]), k;
            for (k = 0; k < 4; ++k)
                if (SUBSTEP_CHOICES[k] == s) a.substep_index = k;
        } else if (!strcmp(o, "--solver") && val) {
            ++i;
            if (!strcmp(val, "soft")) a.solver = GA2D_SOLVER_SOFT_STEP;
            else if (!strcmp(val, "baumgarte")) a.solver = GA2D_SOLVER_PGS_BAUMGARTE;
            else if (!strcmp(val, "ngs")) a.solver = GA2D_SOLVER_PGS_NGS;
            else return usage();
        } else return usage();
    }
    if (scene < 1 || scene > SCENES) return usage();
    if (screenshot && frames <= 0) frames = 120;
    if ((drag_test || throw_test) && frames <= 0) frames = 180;

    if (SDL_Init(SDL_INIT_VIDEO) != 0) {
        fprintf(stderr, "sdl_demo: SDL_Init: %s\n", SDL_GetError());
        return 1;
    }
    window = SDL_CreateWindow("ga2d_physics - SDL demo", SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED,
                              WINDOW_W, WINDOW_H, SDL_WINDOW_SHOWN);
    if (!window) {
        fprintf(stderr, "sdl_demo: SDL_CreateWindow: %s\n", SDL_GetError());
        SDL_Quit();
        return 1;
    }
    /* vsync paces the interactive window; scripted runs go flat out */
    a.ren = SDL_CreateRenderer(window, -1, SDL_RENDERER_ACCELERATED | (frames ? 0 : SDL_RENDERER_PRESENTVSYNC));
    if (!a.ren) a.ren = SDL_CreateRenderer(window, -1, SDL_RENDERER_SOFTWARE);
    if (!a.ren) {
        fprintf(stderr, "sdl_demo: SDL_CreateRenderer: %s\n", SDL_GetError());
        SDL_DestroyWindow(window);
        SDL_Quit();
        return 1;
    }
    load_scene(&a, scene);

    last = SDL_GetPerformanceCounter();
    for (frame = 0; running; ++frame) {
        SDL_Event e;
        while (SDL_PollEvent(&e)) on_event(&a, &e, &running);

        if (throw_test && frame == 10) { /* from the left edge, up and in */
            ga2d_vec from = to_world(&a.cam, 60, HUD_TOP + 0.4 * (WINDOW_H - HUD_TOP - HUD_BOTTOM));
            fake_mouse(&a, SDL_MOUSEBUTTONDOWN, SDL_BUTTON_RIGHT, from, &running);
            fake_mouse(&a, SDL_MOUSEBUTTONUP, SDL_BUTTON_RIGHT, ga2d_vec_add(from, ga2d_vec_make(4, 1)), &running);
        }
        if (drag_test && frame == 20) { /* press on the top body, off its centre */
            ga2d_body_id top = top_body(&a);
            if (!ga2d_body_id_is_null(top)) {
                drag_from = ga2d_transform_apply(ga2d_body_transform(a.world, top), ga2d_vec_make(0.3f, 0.3f));
                fake_mouse(&a, SDL_MOUSEBUTTONDOWN, SDL_BUTTON_LEFT, drag_from, &running);
                if (!a.dragging) { /* a shape smaller than a 1 m box: at its centre */
                    drag_from = ga2d_body_center(a.world, top);
                    fake_mouse(&a, SDL_MOUSEBUTTONDOWN, SDL_BUTTON_LEFT, drag_from, &running);
                }
                if (!a.dragging) fprintf(stderr, "sdl_demo: --drag-test: the pick missed the top body\n");
            }
        }
        if (drag_test && frame > 20) { /* move the cursor 5 m right, 1.5 m up over 60 frames, then hold */
            double t = frame - 20 >= 60 ? 1.0 : (frame - 20) / 60.0;
            fake_mouse(&a, SDL_MOUSEMOTION, 0,
                       ga2d_vec_add(drag_from, ga2d_vec_make((ga2d_real)(5 * t), (ga2d_real)(1.5 * t))), &running);
        }

        if (frames) { /* scripted: one fixed step per frame */
            if (!a.paused) step_world(&a);
        } else {
            Uint64 now = SDL_GetPerformanceCounter();
            int steps = 0;
            accumulator += (double)(now - last) / (double)SDL_GetPerformanceFrequency();
            last = now;
            if (accumulator > 0.25) accumulator = 0.25;
            if (a.paused) accumulator = 0;
            while (accumulator >= STEP_DT && steps < 5) {
                step_world(&a);
                accumulator -= STEP_DT;
                ++steps;
            }
        }

        draw_frame(&a);
        if (frames && frame + 1 >= frames) {
            ga2d_world_counters wc = ga2d_world_get_counters(a.world);
            if (screenshot) {
                if (save_screenshot(a.ren, screenshot)) printf("saved %s\n", screenshot);
                else fprintf(stderr, "sdl_demo: screenshot failed: %s\n", SDL_GetError());
            }
            printf("scene %d (%s): %d frames, %d bodies, %d awake, %d touching, %.3f ms/step "
                   "(substeps %d, %s, sleep %s)%s\n",
                   a.scene, SCENE_NAMES[a.scene], frames, wc.body_count, wc.awake_body_count, wc.touching_count,
                   average_step_ms(&a), SUBSTEP_CHOICES[a.substep_index], SOLVER_NAMES[a.solver],
                   a.sleep_on ? "on" : "off", a.dragging ? ", dragging" : "");
            running = 0;
        }
        SDL_RenderPresent(a.ren);
        if (!frames) SDL_Delay(1); /* vsync paces it; never spin without it */
    }

    ga2d_world_destroy(a.world);
    SDL_DestroyRenderer(a.ren);
    SDL_DestroyWindow(window);
    SDL_Quit();
    return 0;
}
