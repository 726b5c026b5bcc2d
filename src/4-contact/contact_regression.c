/**
 * @file contact_regression.c
 * @brief Logistic regression of two clouds of points at a node (Nairn,
 *        Hammerquist and Smith 2020): the sums of one pass, a Newton step,
 *        the normal (chapter 4b, "the normal by regression").
 */
#include <math.h>
#include <string.h>

#include "contact_regression.h"

/// [regression_add]
void regression_add(double r[REGRESSION_DOUBLES], double xi, double eta,
                    double S, int label)
{
    double v[3] = {xi, eta, 1.0};
    double z = r[0] * xi + r[1] * eta + r[2];
    double sig = 1.0 / (1.0 + exp(-z));
    double e = S * (sig - label), c = S * sig * (1.0 - sig);
    double *g = r + 3, *H = r + 6;
    for (int i = 0, k = 0; i < 3; i++) {
        g[i] += e * v[i];                  /* dL/dw */
        for (int j = i; j < 3; j++)
            H[k++] += c * v[i] * v[j];     /* d2L/dw2, upper triangle */
    }
    r[12] += S;
}
/// [regression_add]

void regression_clear(double r[REGRESSION_DOUBLES])
{
    memset(r + 3, 0, sizeof(double) * (REGRESSION_DOUBLES - 3));
}

/// [regression_newton]
int regression_newton(double r[REGRESSION_DOUBLES])
{
    double W = r[12];
    if (!(W > 0.0))
        return -1;
    double l = REGRESSION_LAMBDA * W, l0 = 1e-6 * l;  /* the offset: barely */
    double g[3] = {r[3] + l * r[0], r[4] + l * r[1], r[5] + l0 * r[2]};
    double a = r[6] + l, b = r[7], c = r[8];      /* H + diag(l, l, l0) */
    double d = r[9] + l, e = r[10], f = r[11] + l0;
    /* Cholesky of [a b c; b d e; c e f], positive definite (l > 0) */
    double L00 = sqrt(a), L10 = b / L00, L20 = c / L00;
    double L11 = sqrt(d - L10 * L10), L21 = (e - L20 * L10) / L11;
    double L22 = sqrt(f - L20 * L20 - L21 * L21);
    double y0 = g[0] / L00, y1 = (g[1] - L10 * y0) / L11;
    double y2 = (g[2] - L20 * y0 - L21 * y1) / L22;
    double x2 = y2 / L22, x1 = (y1 - L21 * x2) / L11;
    double x0 = (y0 - L10 * x1 - L20 * x2) / L00;
    r[0] -= x0;
    r[1] -= x1;
    r[2] -= x2;
    return 0;
}
/// [regression_newton]

int regression_normal(const double r[REGRESSION_DOUBLES], double n[2])
{
    double l = hypot(r[0], r[1]);
    if (!(l > 0.0))
        return 0;
    n[0] = r[0] / l;
    n[1] = r[1] / l;
    return 1;
}
