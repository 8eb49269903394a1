/* svg_writer.h - records a ga2d_physics world through its debug-draw
   interface and writes the run as one animated SVG: SMIL animation, no
   script, so it plays in any browser.  For the examples only: it is not
   part of the library.  Include it after ga2d_physics.h, in one file.

     svgw rec;
     svgw_init(&rec, dt, 2);                 // keep every 2nd step
     svgw_record(&rec, world);               // the state before the run
     for (i = 0; i < steps; ++i) {
         ga2d_world_step(world, dt);
         svgw_record(&rec, world);           // after every step
     }
     svgw_write(&rec, "build/scene.svg", "a caption");  // bytes, or -1
     svgw_free(&rec);

   What it keeps: each body's polygon once, in the body's own frame, and
   per kept frame its transform and its state colour (GA2D_COLOR_*).
   What it writes: a static body as one path, drawn once; a moving body as
   a <g> whose translation and a path whose rotation are animated by
   <animateTransform>, and whose fill changes (awake -> asleep) by a
   discrete <animate>.  Keys that linear interpolation reproduces (within
   1/20000 of the scene and 0.1 degree) are dropped, so a body at rest
   costs two keys.  The run loops, holding its last frame for `hold`
   seconds; a bar along the bottom shows the time.  World y points up:
   the scene sits in a scale(1,-1) group, in a viewBox fitted to where the
   moving bodies went. */
#ifndef SVG_WRITER_H
#define SVG_WRITER_H

#include "ga2d_physics.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#if defined(__GNUC__) || defined(__clang__)
#define SVGW_FN static __attribute__((unused))
#else
#define SVGW_FN static
#endif

typedef struct svgw_sample { double x, y, deg; uint32_t color; } svgw_sample;

typedef struct svgw_body {
    ga2d_body_id id;
    int moving;             /* kinematic or dynamic: a sample per frame */
    ga2d_polygon polygon;   /* in the body frame */
    int first, last;        /* the first and last frame it was drawn in */
    int count, capacity;
    svgw_sample *samples;   /* frames first .. first + count - 1 */
} svgw_body;

typedef struct svgw {
    double frame_dt;        /* seconds between kept frames */
    double hold;            /* seconds the last frame stays before the loop (1) */
    int every, calls, frames;
    int body_count, body_capacity;
    svgw_body *bodies;
    int slot_capacity;
    int *by_slot;           /* body record of each world slot, or -1 */
    const ga2d_world *world;
    int failed;             /* out of memory, or the world refused to draw */
} svgw;

/* Keeps one frame in `every` of a world stepped by step_dt seconds. */
SVGW_FN void svgw_init(svgw *s, double step_dt, int every)
{
    memset(s, 0, sizeof *s);
    s->every = every < 1 ? 1 : every;
    s->frame_dt = step_dt * s->every;
    s->hold = 1.0;
}

SVGW_FN void svgw_free(svgw *s)
{
    int i;
    for (i = 0; i < s->body_count; ++i) free(s->bodies[i].samples);
    free(s->bodies);
    free(s->by_slot);
    memset(s, 0, sizeof *s);
}

/* p grown to hold `need` items of `size` bytes (NULL if out of memory;
   then p is untouched). */
static void *svgw__grow(void *p, int *capacity, int need, size_t size)
{
    int n = *capacity ? *capacity : 16;
    void *q;
    if (need <= *capacity) return p;
    while (n < need) n *= 2;
    q = realloc(p, (size_t)n * size);
    if (q) *capacity = n;
    return q;
}

/* The debug-draw callback: finds (or starts) the body's record and adds
   this frame's transform and colour. */
static void svgw__polygon(ga2d_body_id id, const ga2d_polygon *p, ga2d_transform x, uint32_t color, void *context)
{
    svgw *s = (svgw *)context;
    int slot = (int)id.index1 - 1, r;
    svgw_body *b;
    svgw_sample sample;
    void *q;
    if (s->failed || slot < 0) return;
    if (slot >= s->slot_capacity) {
        int old = s->slot_capacity;
        q = svgw__grow(s->by_slot, &s->slot_capacity, slot + 1, sizeof *s->by_slot);
        if (!q) { s->failed = 1; return; }
        s->by_slot = (int *)q;
        while (old < s->slot_capacity) s->by_slot[old++] = -1;
    }
    r = s->by_slot[slot];
    if (r < 0 || s->bodies[r].id.generation != id.generation) { /* new, or its slot reused */
        q = svgw__grow(s->bodies, &s->body_capacity, s->body_count + 1, sizeof *s->bodies);
        if (!q) { s->failed = 1; return; }
        s->bodies = (svgw_body *)q;
        r = s->body_count++;
        b = &s->bodies[r];
        memset(b, 0, sizeof *b);
        b->id = id;
        b->moving = ga2d_body_get_type(s->world, id) != GA2D_BODY_STATIC;
        b->polygon = *p;
        b->first = s->frames;
        s->by_slot[slot] = r;
    }
    b = &s->bodies[r];
    b->last = s->frames;
    if (b->count > 0 && !b->moving) return;
    sample.x = (double)x.p.x;
    sample.y = (double)x.p.y;
    sample.deg = (double)ga2d_rotor_angle(x.q) * (180 / 3.14159265358979323846);
    if (b->count > 0) { /* unwrap, so that interpolation turns the short way */
        double prev = b->samples[b->count - 1].deg;
        sample.deg += 360 * floor((prev - sample.deg) / 360 + 0.5);
    }
    sample.color = color;
    q = svgw__grow(b->samples, &b->capacity, b->count + 1, sizeof *b->samples);
    if (!q) { s->failed = 1; return; }
    b->samples = (svgw_sample *)q;
    b->samples[b->count++] = sample;
}

/* Call after every step (and once before the first): keeps every
   `every`-th call as a frame. */
SVGW_FN void svgw_record(svgw *s, const ga2d_world *w)
{
    ga2d_debug_draw d = ga2d_default_debug_draw();
    if (s->calls++ % s->every != 0) return;
    d.polygon = svgw__polygon;
    d.context = s;
    s->world = w;
    if (ga2d_world_draw(w, &d) != GA2D_OK) s->failed = 1;
    s->world = NULL;
    ++s->frames;
}

/* ------------------------------------------------------------- writing */
/* v with at most `decimals` decimals, trailing zeros and "-0" dropped */
static void svgw__num(FILE *f, double v, int decimals)
{
    char buf[64];
    int n = snprintf(buf, sizeof buf, "%.*f", decimals, v);
    if (n <= 0 || n >= (int)sizeof buf) { fputs("0", f); return; }
    if (strchr(buf, '.')) {
        while (n > 0 && buf[n - 1] == '0') buf[--n] = '\0';
        if (n > 0 && buf[n - 1] == '.') buf[--n] = '\0';
    }
    fputs(strcmp(buf, "-0") == 0 ? "0" : buf, f);
}

/* component `what` of a sample: 0 x, 1 y, 2 degrees */
static double svgw__get(const svgw_sample *s, int what)
{
    return what == 0 ? s->x : what == 1 ? s->y : s->deg;
}

/* Marks in keep[] the samples that linear interpolation between kept ones
   cannot replace: within `tol` in components first .. last. */
static void svgw__simplify(const svgw_sample *s, int n, int first, int last, double tol, char *keep)
{
    int a = 0, k, j, c;
    memset(keep, 0, (size_t)n);
    keep[0] = keep[n - 1] = 1;
    for (k = 2; k < n; ++k) { /* can the segment a..k stand for a+1 .. k-1? */
        int ok = 1;
        for (j = a + 1; j < k && ok; ++j) {
            double t = (double)(j - a) / (k - a);
            for (c = first; c <= last; ++c) {
                double va = svgw__get(&s[a], c), vk = svgw__get(&s[k], c);
                if (fabs(va + (vk - va) * t - svgw__get(&s[j], c)) > tol) ok = 0;
            }
        }
        if (!ok) keep[a = k - 1] = 1;
    }
}

/* Whether samples 0 .. n-1 stay within tol of sample 0 in those components. */
static int svgw__constant(const svgw_sample *s, int n, int first, int last, double tol)
{
    int i, c;
    for (i = 1; i < n; ++i)
        for (c = first; c <= last; ++c)
            if (fabs(svgw__get(&s[i], c) - svgw__get(&s[0], c)) > tol) return 0;
    return 1;
}

/* text with XML's special characters escaped */
static void svgw__text(FILE *f, const char *t)
{
    for (; t && *t; ++t)
        if (*t == '<') fputs("&lt;", f);
        else if (*t == '>') fputs("&gt;", f);
        else if (*t == '&') fputs("&amp;", f);
        else fputc(*t, f);
}

static void svgw__color(FILE *f, uint32_t color) { fprintf(f, "#%06x", (unsigned)(color & 0xFFFFFFu)); }

/* the opening of an animation element that loops with the run */
static void svgw__anim(FILE *f, const char *element, const char *attribute, double dur)
{
    fprintf(f, "<%s attributeName=\"%s\" dur=\"", element, attribute);
    svgw__num(f, dur, 3);
    fputs("s\" repeatCount=\"indefinite\"", f);
}

/* An animateTransform of components first..last (translate: x, y;
   rotate: degrees) through the kept samples, held before the body's
   first frame and after its last. */
static void svgw__transform_anim(FILE *f, const svgw *s, const svgw_body *b, const char *keep, int first,
                                 int last, int decimals, double dur)
{
    double t0 = b->first * s->frame_dt / dur, tn = (b->first + b->count - 1) * s->frame_dt / dur;
    int i, c, pass;
    svgw__anim(f, "animateTransform", "transform", dur);
    fprintf(f, " type=\"%s\"", first == 2 ? "rotate" : "translate");
    for (pass = 0; pass < 2; ++pass) { /* keyTimes, then values */
        int any = 0;
        fputs(pass == 0 ? " keyTimes=\"" : " values=\"", f);
        if (t0 > 1e-9) { /* held from time 0 */
            if (pass == 0) fputs("0", f);
            else for (c = first; c <= last; ++c) { if (c > first) fputc(',', f); svgw__num(f, svgw__get(&b->samples[0], c), decimals); }
            any = 1;
        }
        for (i = 0; i < b->count; ++i) {
            if (!keep[i]) continue;
            if (any) fputc(';', f);
            any = 1;
            if (pass == 0) {
                double t = (b->first + i) * s->frame_dt / dur;
                if (i == b->count - 1 && tn >= 1 - 1e-9) fputs("1", f);
                else if (t0 > 1e-9 || i > 0) svgw__num(f, t, 5);
                else fputs("0", f);
            } else
                for (c = first; c <= last; ++c) { if (c > first) fputc(',', f); svgw__num(f, svgw__get(&b->samples[i], c), decimals); }
        }
        if (tn < 1 - 1e-9) { /* held to the end of the loop */
            fputc(';', f);
            if (pass == 0) fputs("1", f);
            else for (c = first; c <= last; ++c) { if (c > first) fputc(',', f); svgw__num(f, svgw__get(&b->samples[b->count - 1], c), decimals); }
        }
        fputc('"', f);
    }
    fputs("/>\n", f);
}

/* One body: a <g> placed by its translation, holding a path turned by its
   rotation and filled with its state colour, animated where they change. */
static void svgw__body(FILE *f, const svgw *s, const svgw_body *b, char *keep, double tol, int decimals, double dur)
{
    const svgw_sample *s0 = &b->samples[0];
    int animated = s->frames > 1, i, runs = 1;
    int move = animated && !svgw__constant(b->samples, b->count, 0, 1, tol);
    int turn = animated && !svgw__constant(b->samples, b->count, 2, 2, 0.1);
    for (i = 1; i < b->count; ++i) runs += b->samples[i].color != b->samples[i - 1].color;

    fputs("<g transform=\"translate(", f);
    svgw__num(f, s0->x, decimals);
    fputc(',', f);
    svgw__num(f, s0->y, decimals);
    fputs(")\">", f);
    if (animated && (b->first > 0 || b->last < s->frames - 1)) { /* exists for part of the run */
        svgw__anim(f, "animate", "visibility", dur);
        fputs(" calcMode=\"discrete\" keyTimes=\"0", f);
        if (b->first > 0) { fputc(';', f); svgw__num(f, b->first * s->frame_dt / dur, 5); }
        if (b->last < s->frames - 1) { fputc(';', f); svgw__num(f, (b->last + 1) * s->frame_dt / dur, 5); }
        fprintf(f, "\" values=\"%s%s\"/>", b->first > 0 ? "hidden;visible" : "visible",
                b->last < s->frames - 1 ? ";hidden" : "");
    }
    fputc('\n', f);
    if (move) {
        svgw__simplify(b->samples, b->count, 0, 1, tol, keep);
        svgw__transform_anim(f, s, b, keep, 0, 1, decimals, dur);
    }
    fputs("<path", f);
    if (turn || fabs(s0->deg) > 1e-3) {
        fputs(" transform=\"rotate(", f);
        svgw__num(f, s0->deg, 2);
        fputs(")\"", f);
    }
    fputs(" d=\"M", f);
    for (i = 0; i < b->polygon.count; ++i) {
        fputc(' ', f);
        svgw__num(f, (double)b->polygon.vertices[i].x, decimals);
        fputc(',', f);
        svgw__num(f, (double)b->polygon.vertices[i].y, decimals);
    }
    fputs("Z\" fill=\"", f);
    svgw__color(f, s0->color);
    fputs(turn || (animated && runs > 1) ? "\">\n" : "\"/>\n", f);
    if (turn) {
        svgw__simplify(b->samples, b->count, 2, 2, 0.1, keep);
        svgw__transform_anim(f, s, b, keep, 2, 2, 2, dur);
    }
    if (animated && runs > 1) { /* the colour runs, each from its first frame */
        svgw__anim(f, "animate", "fill", dur);
        fputs(" calcMode=\"discrete\" keyTimes=\"0", f);
        for (i = 1; i < b->count; ++i)
            if (b->samples[i].color != b->samples[i - 1].color) {
                fputc(';', f);
                svgw__num(f, (b->first + i) * s->frame_dt / dur, 5);
            }
        fputs("\" values=\"", f);
        svgw__color(f, s0->color);
        for (i = 1; i < b->count; ++i)
            if (b->samples[i].color != b->samples[i - 1].color) {
                fputc(';', f);
                svgw__color(f, b->samples[i].color);
            }
        fputs("\"/>\n", f);
    }
    if (turn || (animated && runs > 1)) fputs("</path>\n", f);
    fputs("</g>\n", f);
}

/* The world box of the bodies (moving ones; all if none moves) over the
   run.  Returns 0 when there is nothing to frame. */
static int svgw__bounds(const svgw *s, double box[4])
{
    int pass, i, k, v, found = 0;
    for (pass = 0; pass < 2 && !found; ++pass)
        for (i = 0; i < s->body_count; ++i) {
            const svgw_body *b = &s->bodies[i];
            if (pass == 0 && !b->moving) continue;
            for (k = 0; k < b->count; ++k) {
                double c = cos(b->samples[k].deg * (3.14159265358979323846 / 180));
                double sn = sin(b->samples[k].deg * (3.14159265358979323846 / 180));
                for (v = 0; v < b->polygon.count; ++v) {
                    double px = (double)b->polygon.vertices[v].x, py = (double)b->polygon.vertices[v].y;
                    double x = b->samples[k].x + px * c - py * sn, y = b->samples[k].y + px * sn + py * c;
                    if (!found || x < box[0]) box[0] = x;
                    if (!found || y < box[1]) box[1] = y;
                    if (!found || x > box[2]) box[2] = x;
                    if (!found || y > box[3]) box[3] = y;
                    found = 1;
                }
            }
        }
    return found;
}

/* Writes the SVG.  Returns its size in bytes, or -1 (nothing recorded,
   out of memory, or the file could not be written). */
SVGW_FN long svgw_write(const svgw *s, const char *path, const char *caption)
{
    double box[4], w, h, pad, size, tol, dur, run, fs;
    double vx, vy; /* the viewBox's top-left corner, in SVG (y-down) units */
    int i, pass, decimals, max_count = 1;
    long bytes;
    char *keep;
    FILE *f;
    if (s->failed || s->frames == 0 || !svgw__bounds(s, box)) return -1;
    w = box[2] - box[0];
    h = box[3] - box[1];
    size = w > h ? w : h;
    if (size <= 0) size = 1;
    pad = 0.08 * size;
    box[0] -= pad; box[1] -= pad; box[2] += pad; box[3] += pad;
    w = box[2] - box[0];
    h = box[3] - box[1];
    if (w < h / 3) { box[0] -= (h / 3 - w) / 2; w = h / 3; } /* no slivers */
    if (h < w / 3) { box[3] += (w / 3 - h) / 2; /* the extra height goes above, under the caption */ h = w / 3; }
    size = w > h ? w : h;
    tol = size / 20000;
    decimals = (int)ceil(-log10(tol));
    if (decimals < 0) decimals = 0;
    run = (s->frames - 1) * s->frame_dt;
    dur = run + (s->hold > 0 ? s->hold : 0);
    if (dur <= 0) dur = 1;
    vx = box[0];
    vy = -box[3];
    fs = 0.03 * size;

    for (i = 0; i < s->body_count; ++i)
        if (s->bodies[i].count > max_count) max_count = s->bodies[i].count;
    keep = (char *)malloc((size_t)max_count);
    f = keep ? fopen(path, "w") : NULL;
    if (!f) { free(keep); return -1; }

    fprintf(f, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
               "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" viewBox=\"",
            (int)(640 * w / size + 0.5), (int)(640 * h / size + 0.5));
    svgw__num(f, vx, decimals); fputc(' ', f);
    svgw__num(f, vy, decimals); fputc(' ', f);
    svgw__num(f, w, decimals); fputc(' ', f);
    svgw__num(f, h, decimals);
    fputs("\">\n<title>", f);
    svgw__text(f, caption);
    fputs("</title>\n<rect x=\"", f);
    svgw__num(f, vx, decimals); fputs("\" y=\"", f);
    svgw__num(f, vy, decimals); fputs("\" width=\"100%\" height=\"100%\" fill=\"#fbfbf8\"/>\n", f);

    /* the scene, y up; static bodies first, under the moving ones */
    fputs("<g transform=\"scale(1,-1)\" stroke=\"#333\" stroke-linejoin=\"round\" stroke-width=\"", f);
    svgw__num(f, 0.0015 * size, decimals);
    fputs("\">\n", f);
    for (pass = 0; pass < 2; ++pass)
        for (i = 0; i < s->body_count; ++i)
            if (s->bodies[i].moving == pass) svgw__body(f, s, &s->bodies[i], keep, tol, decimals, dur);
    fputs("</g>\n", f);

    /* caption, legend, and a bar that grows with the simulated time */
    fprintf(f, "<g font-family=\"sans-serif\" font-size=\"%.4g\" fill=\"#333\">\n", fs);
    fprintf(f, "<text x=\"%.6g\" y=\"%.6g\">", vx + fs, vy + 1.6 * fs);
    svgw__text(f, caption);
    fputs("</text>\n", f);
    fprintf(f, "<rect x=\"%.6g\" y=\"%.6g\" width=\"%.4g\" height=\"%.4g\" fill=\"#%06x\"/>"
               "<text x=\"%.6g\" y=\"%.6g\">awake</text>\n",
            vx + fs, vy + 2.2 * fs, 0.8 * fs, 0.8 * fs, (unsigned)GA2D_COLOR_AWAKE, vx + 2.1 * fs, vy + 2.9 * fs);
    fprintf(f, "<rect x=\"%.6g\" y=\"%.6g\" width=\"%.4g\" height=\"%.4g\" fill=\"#%06x\"/>"
               "<text x=\"%.6g\" y=\"%.6g\">asleep</text>\n",
            vx + 5.6 * fs, vy + 2.2 * fs, 0.8 * fs, 0.8 * fs, (unsigned)GA2D_COLOR_ASLEEP, vx + 6.7 * fs, vy + 2.9 * fs);
    if (s->frames > 1) {
        fprintf(f, "<rect x=\"%.6g\" y=\"%.6g\" width=\"0\" height=\"%.4g\" fill-opacity=\"0.5\">", vx,
                vy + h - 0.25 * fs, 0.25 * fs);
        svgw__anim(f, "animate", "width", dur);
        fputs(" keyTimes=\"0;", f);
        svgw__num(f, run / dur, 5);
        fputs(";1\" values=\"0;", f);
        svgw__num(f, w, decimals);
        fputc(';', f);
        svgw__num(f, w, decimals);
        fputs("\"/></rect>\n", f);
    }
    fputs("</g>\n</svg>\n", f);
    free(keep);
    bytes = ferror(f) ? -1 : ftell(f);
    if (fclose(f) != 0) bytes = -1;
    return bytes;
}

#endif /* SVG_WRITER_H */
