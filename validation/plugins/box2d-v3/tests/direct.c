/* b2ShapeDistance called directly, without gjk-validate or the adapter: the other side of the test
 * "plugins: box2d-v3: the adapter's answers equal b2ShapeDistance called directly"
 * (equal.py). Linked with the same Box2D objects as gjk2d-box2d3.so, same flags.
 *
 * Usage: box2d3_direct CASES.txt     (equal.py writes it from a gjk-cases/1 file)
 *   per case, three lines:  case NAME
 *                           A n radius px py c s x0 y0 ... x(n-1) y(n-1)
 *                           B n radius px py c s x0 y0 ...
 *   numbers as doubles (repr); each is converted to float as the runner converts a case for a
 *   float implementation (float(x), round to nearest).
 * Prints one line per case: NAME,distance,pAx,pAy,pBx,pBy,iterations with the five numbers in %a
 * (every bit), pA and pB in world coordinates; NAME,refused for a shape of more than
 * B2_MAX_POLYGON_VERTICES points (the runner refuses those without calling the adapter).
 * Exit 2 with one line on stderr for a malformed file. */
#define _POSIX_C_SOURCE 200809L /* getline */

#include "box2d/collision.h"
#include "box2d/math_functions.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct
{
    int n;
    double r, px, py, c, s;
    double pts[2 * B2_MAX_POLYGON_VERTICES];
} Shape;

static void fail(const char* path, long line, const char* what)
{
    fprintf(stderr, "%s:%ld: %s\n", path, line, what);
    exit(2);
}

static double number(char** p, const char* path, long line)
{
    char* end;
    double v = strtod(*p, &end);
    if (end == *p)
        fail(path, line, "expected a number");
    *p = end;
    return v;
}

/* Reads "T n r px py c s x0 y0 ..."; a shape of more than 8 points keeps only its count. */
static void readShape(char* buf, char tag, Shape* s, const char* path, long line)
{
    if (buf[0] != tag || buf[1] != ' ')
        fail(path, line, "expected a shape line");
    char* p = buf + 2;
    s->n = (int)number(&p, path, line);
    if (s->n < 1)
        fail(path, line, "bad point count");
    s->r = number(&p, path, line);
    s->px = number(&p, path, line);
    s->py = number(&p, path, line);
    s->c = number(&p, path, line);
    s->s = number(&p, path, line);
    for (int i = 0; i < s->n && s->n <= B2_MAX_POLYGON_VERTICES; ++i)
    {
        s->pts[2 * i] = number(&p, path, line);
        s->pts[2 * i + 1] = number(&p, path, line);
    }
}

static b2Transform transformOf(const Shape* s)
{
    b2Transform xf;
    xf.p.x = (float)s->px;
    xf.p.y = (float)s->py;
    xf.q.c = (float)s->c;
    xf.q.s = (float)s->s;
    return xf;
}

static b2ShapeProxy proxyOf(const Shape* s)
{
    b2Vec2 pts[B2_MAX_POLYGON_VERTICES];
    for (int i = 0; i < s->n; ++i)
    {
        pts[i].x = (float)s->pts[2 * i];
        pts[i].y = (float)s->pts[2 * i + 1];
    }
    return b2MakeProxy(pts, s->n, (float)s->r);
}

static void answer(const char* name, const Shape* a, const Shape* b)
{
    if (a->n > B2_MAX_POLYGON_VERTICES || b->n > B2_MAX_POLYGON_VERTICES)
    {
        printf("%s,refused\n", name);
        return;
    }
    b2Transform xfA = transformOf(a), xfB = transformOf(b);
    b2DistanceInput in;
    memset(&in, 0, sizeof in);
    in.proxyA = proxyOf(a);
    in.proxyB = proxyOf(b);
    in.transform = b2InvMulTransforms(xfA, xfB);
    in.useRadii = true;
    b2SimplexCache cache = {0};
    b2DistanceOutput o = b2ShapeDistance(&in, &cache, NULL, 0);
    b2Vec2 wa = b2TransformPoint(xfA, o.pointA), wb = b2TransformPoint(xfA, o.pointB);
    printf("%s,%a,%a,%a,%a,%a,%d\n", name, (double)o.distance, (double)wa.x, (double)wa.y,
           (double)wb.x, (double)wb.y, o.iterations);
}

static char* nextLine(FILE* f, char** buf, size_t* cap, long* line)
{
    ssize_t k = getline(buf, cap, f);
    if (k < 0)
        return NULL;
    *line += 1;
    while (k > 0 && ((*buf)[k - 1] == '\n' || (*buf)[k - 1] == '\r'))
        (*buf)[--k] = 0;
    return *buf;
}

int main(int argc, char** argv)
{
    if (argc != 2)
    {
        fprintf(stderr, "usage: %s CASES.txt\n", argv[0]);
        return 2;
    }
    FILE* f = fopen(argv[1], "r");
    if (f == NULL)
        fail(argv[1], 0, "cannot open");
    char *buf = NULL, name[1024];
    size_t cap = 0;
    long line = 0;
    Shape a, b;
    while (nextLine(f, &buf, &cap, &line) != NULL)
    {
        if (strncmp(buf, "case ", 5) != 0 || strlen(buf + 5) >= sizeof name)
            fail(argv[1], line, "expected 'case NAME'");
        strcpy(name, buf + 5);
        if (nextLine(f, &buf, &cap, &line) == NULL)
            fail(argv[1], line, "unexpected end of file");
        readShape(buf, 'A', &a, argv[1], line);
        if (nextLine(f, &buf, &cap, &line) == NULL)
            fail(argv[1], line, "unexpected end of file");
        readShape(buf, 'B', &b, argv[1], line);
        answer(name, &a, &b);
    }
    free(buf);
    fclose(f);
    return 0;
}
