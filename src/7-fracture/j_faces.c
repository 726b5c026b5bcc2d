/**
 * @file j_faces.c
 * @brief The face terms of J and of the interaction integral at a tip
 *        whose crack turns inside the domain (chapter 7b, "A kinked
 *        crack"): the domain form (Shih, Moran and Nakamura 1986; Moran
 *        and Shih 1987) keeps, beside its area integrals, the contour
 *        integral over the crack faces between the inner and the outer
 *        contour, int (W + T) m_1 q ds on traction-free faces, which
 *        vanishes only where the faces run along x1.
 *
 * Behind a kink the auxiliary fields of the interaction integral have
 * their cut along the crack, not along the ray theta = pi (which now runs
 * through material): Williams' functions of theta are continued past +-pi
 * (j_tip_angle()). They still satisfy equilibrium and compatibility in the
 * cut domain, but they are not traction-free on the turned faces, so the
 * face term of M^(m) keeps sigma^m_ij m_j u_i,1 besides the mixed energy.
 */
#include <math.h>
#include <string.h>

#include "j_integral.h"

/** pi */
#define PI 3.14159265358979323846

/** A segment turns from x1 when the sine of its angle to it exceeds
 *  this: a crack grown straight, whose points the material moved by
 *  round-off, keeps its J (and its numbers) as before. */
#define KINK_SINE 1e-6

/** Face points per cell along a face (the midpoint rule). */
#define FACE_POINTS_PER_CELL 4

/** Point @p k back from tip @p T along crack @p c (k = 0: the tip). */
static int back(const Crack *c, const JTip *T, int k)
{
    return T->end ? c->n - 1 - k : k;
}

/// [j_tip_kink]
void j_tip_kink(const Grid *g, const Crack *c, JTip *T, int cells)
{
    T->kink = 0;
    for (int k = 1; k < c->n; k++) {
        int a = back(c, T, k - 1), b = back(c, T, k);
        if (fabs(c->x[a] - T->x) >= cells * g->dx ||
            fabs(c->y[a] - T->y) >= cells * g->dy)
            return;                     /* it has left the domain straight */
        double tx = c->x[a] - c->x[b], ty = c->y[a] - c->y[b];
        double len = hypot(tx, ty);
        double sine = (tx * T->ey - ty * T->ex) / len;
        double cosine = (tx * T->ex + ty * T->ey) / len;
        if (fabs(sine) > KINK_SINE || cosine < 0.0) {
            T->kink = k;                /* segment k turns: point k - 1 */
            return;
        }
    }
}
/// [j_tip_kink]

/** The angle of (x1, x2) in (0, 2 pi]: behind the tip near pi. */
static double behind(double x1, double x2)
{
    double a = atan2(x2, x1);
    return a <= 0.0 ? a + 2.0 * PI : a;
}

/// [j_tip_angle]
double j_tip_angle(const Crack *c, const JTip *T, double x1, double x2)
{
    double theta = atan2(x2, x1);
    if (!T->kink)
        return theta;
    /* phi: the crack's angle at the point's radius r, walked back from
       the kink (pi up to it); theta is taken in (phi - 2 pi, phi] */
    double r = hypot(x1, x2), phi = PI;
    double e1[2] = {T->ex, T->ey}, e2[2] = {-T->ey, T->ex};
    for (int k = T->kink; k < c->n; k++) {
        int ia = back(c, T, k - 1), ib = back(c, T, k);
        double ax = c->x[ia] - T->x, ay = c->y[ia] - T->y;
        double bx = c->x[ib] - T->x, by = c->y[ib] - T->y;
        double a[2] = {e1[0] * ax + e1[1] * ay, e2[0] * ax + e2[1] * ay};
        double b[2] = {e1[0] * bx + e1[1] * by, e2[0] * bx + e2[1] * by};
        double ra = hypot(a[0], a[1]), rb = hypot(b[0], b[1]);
        if (ra >= r)
            break;                      /* nearer than this segment */
        if (rb >= r) {                  /* |a + s (b - a)| = r */
            double d[2] = {b[0] - a[0], b[1] - a[1]};
            double dd = d[0] * d[0] + d[1] * d[1], ad = a[0] * d[0] + a[1] * d[1];
            double s = (-ad + sqrt(fmax(0.0, ad * ad - dd * (ra * ra - r * r)))) / dd;
            phi = behind(a[0] + s * d[0], a[1] + s * d[1]);
            break;
        }
        phi = behind(b[0], b[1]);       /* beyond its end: the end's */
    }
    if (theta > phi)
        theta -= 2.0 * PI;
    else if (theta <= phi - 2.0 * PI)
        theta += 2.0 * PI;
    return theta;
}
/// [j_tip_angle]

/** The part of the segment a + s (b - a), s in [0, 1], inside the square
 *  of half-sides hx, hy about (cx, cy) (Liang and Barsky): @p s0, @p s1.
 *  @return 0 when none of it is. */
static int clip(const double a[2], const double b[2], double cx, double cy,
                double hx, double hy, double *s0, double *s1)
{
    double d[2] = {b[0] - a[0], b[1] - a[1]};
    double p[4] = {-d[0], d[0], -d[1], d[1]};
    double q[4] = {a[0] - (cx - hx), (cx + hx) - a[0], a[1] - (cy - hy),
                   (cy + hy) - a[1]};
    *s0 = 0.0;
    *s1 = 1.0;
    for (int i = 0; i < 4; i++) {
        if (p[i] == 0.0) {
            if (q[i] < 0.0)
                return 0;
            continue;
        }
        double s = q[i] / p[i];
        if (p[i] < 0.0)
            *s0 = fmax(*s0, s);
        else
            *s1 = fmin(*s1, s);
    }
    return *s1 > *s0;
}

/** The fields on one face at a face point: the mean over the points
 *  beside it. */
typedef struct FaceSide {
    double w;          /**< sum of the weights (0: no point) */
    double WT;         /**< W + T */
    double s[2][2];    /**< stress */
    double d[2];       /**< u_i,1 (global i) */
} FaceSide;

/** Does the line from @p g to point (px, py) cross a segment of crack
 *  @p c other than segment @p k (points k, k + 1, which g lies on)? */
static int hidden(const Crack *c, int k, const double g[2], double px, double py)
{
    double p[2] = {px, py};
    for (int j = 0; j + 1 < c->n; j++) {
        if (j == k)
            continue;
        double a[2] = {c->x[j], c->y[j]}, b[2] = {c->x[j + 1], c->y[j + 1]};
        if (fmax(a[0], b[0]) < fmin(g[0], px) || fmin(a[0], b[0]) > fmax(g[0], px) ||
            fmax(a[1], b[1]) < fmin(g[1], py) || fmin(a[1], b[1]) > fmax(g[1], py))
            continue;
        if (crack_segments_meet(g, p, a, b))
            return 1;
    }
    return 0;
}

/// [j_face_side]
/** The fields beside face point @p g of segment @p k, on the side of
 *  its normal @p n times @p side, from the points (of the @p nn in
 *  JState::near) within one cell of g that see g without crossing the
 *  crack, weighted by 1 - distance / cell. */
static void face_side(const Sim *sim, const JState *S, const JTip *T,
                      const Crack *c, int k, int nn, const double g[2],
                      const double n[2], int side, FaceSide *f)
{
    const Particles *P = &sim->pts;
    const Grid *gr = &sim->grid;
    double R = fmin(gr->dx, gr->dy);
    memset(f, 0, sizeof *f);
    for (int i = 0; i < nn; i++) {
        int p = S->near[i];
        double dx = P->x[p] - g[0], dy = P->y[p] - g[1];
        double dist = hypot(dx, dy);
        if (dist >= R || side * (dx * n[0] + dy * n[1]) <= 0.0 ||
            hidden(c, k, g, P->x[p], P->y[p]))
            continue;
        JPoint jp;
        j_point_gradients(sim, S, p, &jp);
        double w = 1.0 - dist / R;
        double W = j_strain_energy(P, p);
        double T2 = 0.5 * (P->vx[p] * P->vx[p] + P->vy[p] * P->vy[p]);
        f->w += w;
        f->WT += w * (W + P->m[p] / P->vol[p] * T2);
        f->s[0][0] += w * P->sxx[p];
        f->s[1][1] += w * P->syy[p];
        f->s[0][1] += w * P->sxy[p];
        for (int l = 0; l < 2; l++)
            f->d[l] += w * (jp.D[l][0] * T->ex + jp.D[l][1] * T->ey);
    }
    if (f->w > 0.0) {
        f->WT /= f->w;
        f->s[0][0] /= f->w;
        f->s[1][1] /= f->w;
        f->s[0][1] /= f->w;
        f->d[0] /= f->w;
        f->d[1] /= f->w;
    }
    f->s[1][0] = f->s[0][1];
}
/// [j_face_side]

/** The material of the points beside a face (those of the nearest of
 *  the @p nn in JState::near). */
static int face_material(const Sim *sim, const JState *S, int nn,
                         const double g[2])
{
    const Particles *P = &sim->pts;
    int best = 0;
    double near = INFINITY;
    for (int i = 0; i < nn; i++) {
        int p = S->near[i];
        double d = hypot(P->x[p] - g[0], P->y[p] - g[1]);
        if (d < near) {
            near = d;
            best = P->mat[p];
        }
    }
    return best;
}

/// [j_face_terms]
void j_face_terms(const Sim *sim, const JState *S, JTip *T)
{
    const Grid *g = &sim->grid;
    const Crack *c = &cracks_of(sim)->crack[T->crack];
    const JSettings *j = &S->set[T->crack];
    int strain = sim->scene.run.plane == PLANE_STRAIN, cells = 0;
    for (int m = 0; m < j->ncontours; m++)
        cells = j->contour[m] > cells ? j->contour[m] : cells;
    double e[2] = {T->ex, T->ey}, eps = 1e-9 * g->dx;
    /* the points within a cell of the widest domain */
    const Particles *P = &sim->pts;
    int nn = 0;
    for (int p = 0; p < P->n && p < S->npoints; p++)
        if (fabs(P->x[p] - T->x) < (cells + 1) * g->dx &&
            fabs(P->y[p] - T->y) < (cells + 1) * g->dy)
            S->near[nn++] = p;
    for (int k = T->kink; k < c->n; k++) {
        int ia = back(c, T, k - 1), ib = back(c, T, k);
        int seg = ia < ib ? ia : ib;    /* its index in the crack */
        double a[2] = {c->x[ia], c->y[ia]}, b[2] = {c->x[ib], c->y[ib]};
        double s0, s1;
        if (!clip(a, b, T->x, T->y, cells * g->dx, cells * g->dy, &s0, &s1))
            continue;
        double len = hypot(b[0] - a[0], b[1] - a[1]);
        double t[2] = {(b[0] - a[0]) / len, (b[1] - a[1]) / len};
        double n[2] = {-t[1], t[0]};    /* a normal of the face */
        int nq = (int)ceil((s1 - s0) * len * FACE_POINTS_PER_CELL / fmin(g->dx, g->dy));
        double ds = (s1 - s0) * len / nq;
        for (int i = 0; i < nq; i++) {
            double s = s0 + (i + 0.5) * (s1 - s0) / nq;
            double x[2] = {a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1])};
            /* per side (+n, -n): the fields, and the term (W + T) m_1 and
               sigma eps^m m_1 - sigma^m m u_,1 with m = -side n, the normal
               out of that side's material */
            double fJ = 0.0, fM[2] = {0.0, 0.0};
            const Material *mt = &sim->scene.mat[face_material(sim, S, nn, x)];
            for (int side = -1; side <= 1; side += 2) {
                FaceSide f;
                face_side(sim, S, T, c, seg, nn, x, n, side, &f);
                if (!(f.w > 0.0))
                    continue;
                double mo[2] = {-side * n[0], -side * n[1]};
                double m1 = mo[0] * e[0] + mo[1] * e[1];
                fJ += f.WT * m1;
                double sa[2][2][2], dua[2][2][2];
                k_auxiliary(T, c, mt, strain, x[0] + side * eps * n[0],
                            x[1] + side * eps * n[1], sa, dua);
                for (int md = 0; md < 2; md++) {
                    double W12 = 0.0, sm = 0.0;
                    for (int p = 0; p < 2; p++) {
                        for (int q = 0; q < 2; q++)
                            W12 += f.s[p][q] * 0.5 * (dua[md][p][q] + dua[md][q][p]);
                        sm += (sa[md][p][0] * mo[0] + sa[md][p][1] * mo[1]) * f.d[p];
                    }
                    fM[md] += W12 * m1 - sm;
                }
            }
            for (int m = 0; m < j->ncontours; m++) {
                double dq[2];
                double q = j_weight(g, T, j->contour[m], x[0], x[1], dq);
                if (q == 0.0)
                    continue;
                T->J[m] += fJ * q * ds;
                T->Jface[m] += fJ * q * ds;
                T->KI[m] += fM[0] * q * ds;
                T->KIface[m] += fM[0] * q * ds;
                T->KII[m] += fM[1] * q * ds;
                T->KIIface[m] += fM[1] * q * ds;
            }
        }
    }
}
/// [j_face_terms]
