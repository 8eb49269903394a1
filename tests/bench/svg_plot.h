/* svg_plot.h - a scatter plot of error against cost, written as SVG, for
   trade.c.  Each point is one configuration: its x a cost (ms per step),
   its y an error (log scale), a label, a series (its colour) and a marker
   (its shape).  The Pareto front (the points no other point beats in both
   cost and error) is worked out here and drawn as a highlighted line
   through those points, each ringed and labelled in bold.

     svgp_plot p;
     svgp_init(&p, "title", "subtitle", "ms per step", "error");
     svgp_series(&p, 0, "soft step");   // names for series colours
     svgp_marker(&p, 0, "float");       // and for marker shapes
     svgp_add(&p, 0.42, 1.7e-2, "soft 4", 0, 0);
     svgp_write(&p, "build/trade/plot.svg");  // 0, or -1 if not written

   x runs on a log scale when the costs span more than a factor of 10,
   else on a linear one.  An error of 0 (or below the axis) is drawn on
   the axis with an open triangle.  Labels are placed where they collide
   with no other label or point, joined by a thin line when placed away
   from their point.  libc + libm only. */
#ifndef GA2D_BENCH_SVG_PLOT_H
#define GA2D_BENCH_SVG_PLOT_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#if defined(__GNUC__) || defined(__clang__)
#define SVGP_FN static __attribute__((unused))
#else
#define SVGP_FN static
#endif

#define SVGP_MAX_POINTS 128
#define SVGP_MAX_SERIES 8
#define SVGP_MAX_MARKERS 2
#define SVGP_LABEL 48

typedef struct svgp_point {
    double x, y;
    char label[SVGP_LABEL];
    int series, marker;
    int pareto;
} svgp_point;

typedef struct svgp_plot {
    const char *title, *subtitle, *xlabel, *ylabel;
    const char *series_name[SVGP_MAX_SERIES];
    const char *marker_name[SVGP_MAX_MARKERS];
    int count;
    svgp_point points[SVGP_MAX_POINTS];
} svgp_plot;

/* The page: plot area inside the margins; the legend to its right. */
#define SVGP_W 1100.0
#define SVGP_H 700.0
#define SVGP_LEFT 84.0
#define SVGP_RIGHT 210.0
#define SVGP_TOP 74.0
#define SVGP_BOTTOM 64.0
#define SVGP_FONT 11.0

static const char *const svgp__colors[SVGP_MAX_SERIES] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd",
                                                          "#8c564b", "#e377c2", "#17becf", "#7f7f7f"};

SVGP_FN void svgp_init(svgp_plot *p, const char *title, const char *subtitle, const char *xlabel, const char *ylabel)
{
    memset(p, 0, sizeof *p);
    p->title = title;
    p->subtitle = subtitle;
    p->xlabel = xlabel;
    p->ylabel = ylabel;
}

SVGP_FN void svgp_series(svgp_plot *p, int i, const char *name)
{
    if (i >= 0 && i < SVGP_MAX_SERIES) p->series_name[i] = name;
}

SVGP_FN void svgp_marker(svgp_plot *p, int i, const char *name)
{
    if (i >= 0 && i < SVGP_MAX_MARKERS) p->marker_name[i] = name;
}

/* Adds a point; points past SVGP_MAX_POINTS, or with a cost that is not
   finite and positive, or an error that is not finite, are left out
   (returns 0). */
SVGP_FN int svgp_add(svgp_plot *p, double x, double y, const char *label, int series, int marker)
{
    svgp_point *q;
    if (p->count >= SVGP_MAX_POINTS || !(x > 0) || !isfinite(x) || !isfinite(y)) return 0;
    q = &p->points[p->count++];
    q->x = x;
    q->y = y;
    snprintf(q->label, sizeof q->label, "%s", label);
    q->series = series >= 0 && series < SVGP_MAX_SERIES ? series : 0;
    q->marker = marker >= 0 && marker < SVGP_MAX_MARKERS ? marker : 0;
    q->pareto = 0;
    return 1;
}

/* Marks the non-dominated points: none other is at most as costly and at
   most as wrong, and strictly better in one of the two. */
SVGP_FN void svgp_pareto(svgp_plot *p)
{
    int i, j;
    for (i = 0; i < p->count; ++i) {
        const svgp_point *a = &p->points[i];
        p->points[i].pareto = 1;
        for (j = 0; j < p->count; ++j) {
            const svgp_point *b = &p->points[j];
            if (j != i && b->x <= a->x && b->y <= a->y && (b->x < a->x || b->y < a->y)) {
                p->points[i].pareto = 0;
                break;
            }
        }
    }
}

/* ------------------------------------------------------------ axes */
typedef struct svgp__axis {
    int log;
    double lo, hi;   /* data range shown (log: powers of 10) */
    double from, to; /* pixel range */
} svgp__axis;

static double svgp__map(const svgp__axis *a, double v)
{
    double t = a->log ? (log10(v) - log10(a->lo)) / (log10(a->hi) - log10(a->lo)) : (v - a->lo) / (a->hi - a->lo);
    return a->from + t * (a->to - a->from);
}

/* A linear step of 1, 2 or 5 times a power of ten giving about 6 ticks. */
static double svgp__nice_step(double span)
{
    double raw = span / 6, mag = pow(10, floor(log10(raw))), f = raw / mag;
    return (f < 1.5 ? 1 : f < 3.5 ? 2 : f < 7.5 ? 5 : 10) * mag;
}

static void svgp__fit(svgp__axis *a, double lo, double hi, int force_log)
{
    a->log = force_log || (lo > 0 && hi / lo > 10);
    if (a->log) {
        a->lo = pow(10, floor(log10(lo)));
        a->hi = pow(10, ceil(log10(hi)));
        if (a->hi <= a->lo) a->hi = a->lo * 10;
    } else {
        double step = svgp__nice_step(hi - lo > 0 ? hi - lo : (hi > 0 ? hi : 1));
        a->lo = floor(lo / step) * step;
        a->hi = ceil(hi / step) * step;
        if (a->lo > 0 && a->lo <= 2 * step) a->lo = 0; /* keep 0 in view when it is close */
        if (a->hi <= a->lo) a->hi = a->lo + step;
    }
}

/* A tick label: plain decimals for 1e-3 .. 1e4, else 1e-5 style. */
static void svgp__tick_text(double v, char *out, size_t n)
{
    if (v == 0)
        snprintf(out, n, "0");
    else if (fabs(v) >= 1e-3 && fabs(v) < 1e4)
        snprintf(out, n, "%g", v);
    else
        snprintf(out, n, "%.0e", v);
}

/* ------------------------------------------------------------ labels */
typedef struct svgp__box {
    double x0, y0, x1, y1;
} svgp__box;

static int svgp__overlap(svgp__box a, svgp__box b) { return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1; }

static double svgp__text_width(const char *s, double size) { return 0.58 * size * (double)strlen(s); }

static void svgp__escape(FILE *f, const char *s)
{
    for (; *s; ++s) {
        if (*s == '<')
            fputs("&lt;", f);
        else if (*s == '>')
            fputs("&gt;", f);
        else if (*s == '&')
            fputs("&amp;", f);
        else
            fputc(*s, f);
    }
}

static void svgp__marker_path(FILE *f, int marker, double x, double y, double r, const char *color, int below)
{
    if (below) /* an error below the axis: an open triangle on it, pointing down */
        fprintf(f,
                "<path d=\"M%.1f %.1f L%.1f %.1f L%.1f %.1f Z\" fill=\"white\" stroke=\"%s\" stroke-width=\"1.6\"/>\n",
                x - r, y - r, x + r, y - r, x, y + r * 0.8, color);
    else if (marker == 0)
        fprintf(f, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"%.1f\" fill=\"%s\" stroke=\"white\" stroke-width=\"0.8\"/>\n",
                x, y, r, color);
    else
        fprintf(f,
                "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"white\" stroke=\"%s\" "
                "stroke-width=\"1.8\"/>\n",
                x - r * 0.85, y - r * 0.85, 1.7 * r, 1.7 * r, color);
}

static int svgp__cmp_x(const void *a, const void *b)
{
    const svgp_point *p = *(const svgp_point *const *)a, *q = *(const svgp_point *const *)b;
    return (p->x > q->x) - (p->x < q->x);
}

/* Writes the plot; 0, or -1 if the file could not be written. */
SVGP_FN int svgp_write(svgp_plot *p, const char *path)
{
    FILE *f;
    svgp__axis ax, ay;
    double xlo = HUGE_VAL, xhi = 0, ylo = HUGE_VAL, yhi = 0, v;
    svgp__box taken[2 * SVGP_MAX_POINTS];
    const svgp_point *front[SVGP_MAX_POINTS];
    int ntaken = 0, nfront = 0, any_below = 0, i, k, pass;
    char text[32];

    svgp_pareto(p);
    for (i = 0; i < p->count; ++i) {
        const svgp_point *q = &p->points[i];
        xlo = q->x < xlo ? q->x : xlo;
        xhi = q->x > xhi ? q->x : xhi;
        if (q->y > 0) {
            ylo = q->y < ylo ? q->y : ylo;
            yhi = q->y > yhi ? q->y : yhi;
        }
    }
    if (p->count == 0) xlo = xhi = 1;
    if (!(ylo <= yhi)) ylo = yhi = 1; /* no positive error */
    /* a little room either side of the costs */
    if (xhi / xlo > 10) {
        xlo /= 1.15;
        xhi *= 1.15;
    } else {
        double pad = 0.05 * (xhi - xlo > 0 ? xhi - xlo : xhi);
        xlo -= pad;
        xhi += pad;
        if (xlo < 0) xlo = 0;
    }
    svgp__fit(&ax, xlo, xhi, 0);
    svgp__fit(&ay, ylo / 1.5, yhi * 1.5, 1); /* a point never sits on the frame */
    ax.from = SVGP_LEFT;
    ax.to = SVGP_W - SVGP_RIGHT;
    ay.from = SVGP_H - SVGP_BOTTOM;
    ay.to = SVGP_TOP;

    f = fopen(path, "w");
    if (!f) return -1;
    fprintf(f,
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" viewBox=\"0 0 %.0f %.0f\" "
            "font-family=\"Helvetica, Arial, sans-serif\" font-size=\"%.0f\">\n",
            SVGP_W, SVGP_H, SVGP_W, SVGP_H, SVGP_FONT);
    fprintf(f, "<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n");
    fprintf(f, "<text x=\"%.1f\" y=\"26\" font-size=\"17\" font-weight=\"bold\">", SVGP_LEFT);
    svgp__escape(f, p->title);
    fprintf(f, "</text>\n<text x=\"%.1f\" y=\"46\" font-size=\"12\" fill=\"#555\">", SVGP_LEFT);
    svgp__escape(f, p->subtitle);
    fprintf(f, "</text>\n");

    /* grid and ticks */
    fprintf(f, "<g stroke=\"#e4e4e4\" stroke-width=\"1\">\n");
    if (ay.log)
        for (v = ay.lo; v <= ay.hi * 1.0001; v *= 10) {
            /* minor lines only while the decades are tall enough to show them */
            for (k = 2; k < 10 && v * k < ay.hi && log10(ay.hi / ay.lo) <= 8; ++k)
                fprintf(f, "<line x1=\"%.1f\" x2=\"%.1f\" y1=\"%.1f\" y2=\"%.1f\" stroke=\"#f3f3f3\"/>\n", ax.from,
                        ax.to, svgp__map(&ay, v * k), svgp__map(&ay, v * k));
            fprintf(f, "<line x1=\"%.1f\" x2=\"%.1f\" y1=\"%.1f\" y2=\"%.1f\"/>\n", ax.from, ax.to, svgp__map(&ay, v),
                    svgp__map(&ay, v));
        }
    if (ax.log) {
        for (v = ax.lo; v <= ax.hi * 1.0001; v *= 10) {
            for (k = 2; k < 10 && v * k < ax.hi; ++k)
                fprintf(f, "<line y1=\"%.1f\" y2=\"%.1f\" x1=\"%.1f\" x2=\"%.1f\" stroke=\"#f3f3f3\"/>\n", ay.from,
                        ay.to, svgp__map(&ax, v * k), svgp__map(&ax, v * k));
            fprintf(f, "<line y1=\"%.1f\" y2=\"%.1f\" x1=\"%.1f\" x2=\"%.1f\"/>\n", ay.from, ay.to, svgp__map(&ax, v),
                    svgp__map(&ax, v));
        }
    } else {
        double step = svgp__nice_step(ax.hi - ax.lo);
        for (v = ax.lo; v <= ax.hi + step * 1e-6; v += step)
            fprintf(f, "<line y1=\"%.1f\" y2=\"%.1f\" x1=\"%.1f\" x2=\"%.1f\"/>\n", ay.from, ay.to, svgp__map(&ax, v),
                    svgp__map(&ax, v));
    }
    fprintf(f, "</g>\n<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"none\" stroke=\"#333\"/>\n",
            ax.from, ay.to, ax.to - ax.from, ay.from - ay.to);
    fprintf(f, "<g fill=\"#333\">\n");
    for (v = ay.lo; v <= ay.hi * 1.0001; v *= 10) {
        svgp__tick_text(v, text, sizeof text);
        fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"end\">%s</text>\n", ax.from - 6, svgp__map(&ay, v) + 4,
                text);
    }
    if (ax.log) {
        for (v = ax.lo; v <= ax.hi * 1.0001; v *= 10) {
            svgp__tick_text(v, text, sizeof text);
            fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\">%s</text>\n", svgp__map(&ax, v),
                    ay.from + 16, text);
        }
    } else {
        double step = svgp__nice_step(ax.hi - ax.lo);
        for (v = ax.lo; v <= ax.hi + step * 1e-6; v += step) {
            svgp__tick_text(fabs(v) < step * 1e-6 ? 0 : v, text, sizeof text);
            fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\">%s</text>\n", svgp__map(&ax, v),
                    ay.from + 16, text);
        }
    }
    fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\" font-size=\"13\">", (ax.from + ax.to) / 2,
            SVGP_H - 18);
    svgp__escape(f, p->xlabel);
    fprintf(f, "%s</text>\n", ax.log ? " (log scale)" : "");
    fprintf(f, "<text transform=\"translate(22 %.1f) rotate(-90)\" text-anchor=\"middle\" font-size=\"13\">",
            (ay.from + ay.to) / 2);
    svgp__escape(f, p->ylabel);
    fprintf(f, " (log scale)</text>\n</g>\n");

    /* the Pareto front, under the points */
    for (i = 0; i < p->count; ++i)
        if (p->points[i].pareto) front[nfront++] = &p->points[i];
    qsort(front, (size_t)nfront, sizeof front[0], svgp__cmp_x);
    if (nfront > 0) {
        fprintf(f, "<polyline fill=\"none\" stroke=\"#ffb000\" stroke-opacity=\"0.45\" stroke-width=\"9\" "
                   "stroke-linejoin=\"round\" stroke-linecap=\"round\" points=\"");
        for (i = 0; i < nfront; ++i) {
            double y = front[i]->y > ay.lo ? front[i]->y : ay.lo;
            fprintf(f, "%s%.1f,%.1f", i ? " " : "", svgp__map(&ax, front[i]->x), svgp__map(&ay, y));
        }
        fprintf(f, "\"/>\n");
    }

    /* points: every marker's box is taken before any label goes down */
    for (i = 0; i < p->count; ++i) {
        const svgp_point *q = &p->points[i];
        int below = q->y < ay.lo;
        double x = svgp__map(&ax, q->x), y = svgp__map(&ay, below ? ay.lo : q->y);
        any_below |= below;
        if (q->pareto)
            fprintf(f,
                    "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"9\" fill=\"none\" stroke=\"#b36b00\" stroke-width=\"1.5\"/>\n",
                    x, y);
        svgp__marker_path(f, q->marker, x, y, 5, svgp__colors[q->series], below);
        taken[ntaken].x0 = x - 6;
        taken[ntaken].x1 = x + 6;
        taken[ntaken].y0 = y - 6;
        taken[ntaken].y1 = y + 6;
        ++ntaken;
    }

    /* labels: the front's first, then the rest; each at the first free
       place on rings around its point */
    for (pass = 0; pass < 2; ++pass)
        for (i = 0; i < p->count; ++i) {
            static const double dirs[8][2] = {{1, 0}, {-1, 0}, {0, -1}, {0, 1}, {1, -1}, {-1, -1}, {1, 1}, {-1, 1}};
            const svgp_point *q = &p->points[i];
            int below = q->y < ay.lo, placed = 0, ring, d;
            double size = q->pareto ? SVGP_FONT + 0.5 : SVGP_FONT - 1;
            double x = svgp__map(&ax, q->x), y = svgp__map(&ay, below ? ay.lo : q->y);
            double w = svgp__text_width(q->label, size), h = size;
            svgp__box b = {0, 0, 0, 0};
            if (q->pareto != (pass == 0)) continue;
            for (ring = 1; ring <= 6 && !placed; ++ring)
                for (d = 0; d < 8 && !placed; ++d) {
                    double gap = 4 + 11 * (ring - 1);
                    double cx = x + dirs[d][0] * (gap + 6 + w / 2), cy = y + dirs[d][1] * (gap + 4 + h / 2);
                    b.x0 = cx - w / 2;
                    b.x1 = cx + w / 2;
                    b.y0 = cy - h / 2 - 1;
                    b.y1 = cy + h / 2 + 1;
                    if (b.x0 < ax.from + 2 || b.x1 > ax.to - 2 || b.y0 < ay.to + 2 || b.y1 > ay.from - 2) continue;
                    for (k = 0; k < ntaken && !svgp__overlap(b, taken[k]); ++k) {}
                    placed = k == ntaken;
                    if (placed && ring > 1)
                        fprintf(f,
                                "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#999\" "
                                "stroke-width=\"0.7\"/>\n",
                                x, y, cx - dirs[d][0] * w / 2, cy - dirs[d][1] * h / 2);
                }
            if (!placed) { /* crowded: to the right, over whatever is there */
                b.x0 = x + 8;
                b.x1 = x + 8 + w;
                b.y0 = y - h / 2 - 1;
                b.y1 = y + h / 2 + 1;
            }
            if (ntaken < 2 * SVGP_MAX_POINTS) taken[ntaken++] = b;
            fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" font-size=\"%.1f\" fill=\"%s\"%s>", b.x0, b.y1 - 3, size,
                    q->pareto ? "#000" : "#444", q->pareto ? " font-weight=\"bold\"" : "");
            svgp__escape(f, q->label);
            fprintf(f, "</text>\n");
        }

    /* legend */
    {
        double lx = SVGP_W - SVGP_RIGHT + 18, ly = SVGP_TOP + 8;
        fprintf(f, "<g font-size=\"12\">\n");
        for (i = 0; i < SVGP_MAX_SERIES; ++i) {
            if (!p->series_name[i]) continue;
            fprintf(f, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"5\" fill=\"%s\"/>", lx + 6, ly, svgp__colors[i]);
            fprintf(f, "<text x=\"%.1f\" y=\"%.1f\">", lx + 18, ly + 4);
            svgp__escape(f, p->series_name[i]);
            fprintf(f, "</text>\n");
            ly += 20;
        }
        ly += 8;
        for (i = 0; i < SVGP_MAX_MARKERS; ++i) {
            if (!p->marker_name[i]) continue;
            svgp__marker_path(f, i, lx + 6, ly, 5, "#555", 0);
            fprintf(f, "<text x=\"%.1f\" y=\"%.1f\">", lx + 18, ly + 4);
            svgp__escape(f, p->marker_name[i]);
            fprintf(f, "</text>\n");
            ly += 20;
        }
        ly += 8;
        fprintf(f,
                "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#ffb000\" stroke-opacity=\"0.45\" "
                "stroke-width=\"9\" stroke-linecap=\"round\"/>",
                lx, ly, lx + 12, ly);
        fprintf(f, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"9\" fill=\"none\" stroke=\"#b36b00\" stroke-width=\"1.5\"/>",
                lx + 6, ly);
        fprintf(f, "<text x=\"%.1f\" y=\"%.1f\">Pareto front</text>\n", lx + 18, ly + 4);
        fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" fill=\"#555\" font-size=\"11\">(nothing is both</text>\n", lx + 18,
                ly + 20);
        fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" fill=\"#555\" font-size=\"11\">cheaper and better)</text>\n", lx + 18,
                ly + 34);
        ly += 56;
        if (any_below) {
            fprintf(
                f,
                "<path d=\"M%.1f %.1f L%.1f %.1f L%.1f %.1f Z\" fill=\"white\" stroke=\"#555\" stroke-width=\"1.6\"/>",
                lx + 1, ly - 5, lx + 11, ly - 5, lx + 6, ly + 4);
            fprintf(f, "<text x=\"%.1f\" y=\"%.1f\">error 0 (below the axis)</text>\n", lx + 18, ly + 4);
        }
        fprintf(f, "</g>\n");
    }
    fprintf(f, "</svg>\n");
    return fclose(f) == 0 ? 0 : -1;
}

#endif
