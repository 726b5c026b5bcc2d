/**
 * @file particles.h
 * @brief Material points stored as a structure of plain arrays.
 */
#ifndef MPM_PARTICLES_H
#define MPM_PARTICLES_H

/// [particles]
/** All material points of a run; index p runs over 0 .. n-1 in every array. */
typedef struct Particles {
    int n;          /**< number of points */
    int cap;        /**< allocated length of every array */
    double *x;      /**< position x */
    double *y;      /**< position y */
    double *vx;     /**< velocity x */
    double *vy;     /**< velocity y */
    double *m;      /**< mass m_p */
    double *vol;    /**< initial volume m_p / rho_p (area times thickness) */
    double *sxx;    /**< stress xx */
    double *syy;    /**< stress yy */
    double *sxy;    /**< stress xy */
    double *exx;    /**< strain xx */
    double *eyy;    /**< strain yy */
    double *exy;    /**< tensor shear strain xy (half the engineering strain) */
    int *mat;       /**< material index */
    int *body;      /**< body index */
    int *cell;      /**< Task 0: lower-left node of the point's cell this step */
    double *xi;     /**< Task 0: local x coordinate in that cell */
    double *eta;    /**< Task 0: local y coordinate in that cell */
} Particles;
/// [particles]

/** @brief Allocate room for @p cap points (n = 0). @return 0, or -1 on failure. */
int particles_init(Particles *P, int cap);

/** @brief Grow the arrays to hold at least @p cap points. @return 0 or -1. */
int particles_reserve(Particles *P, int cap);

/** @brief Append one point at rest and unstrained. @return its index, or
 *         -1 out of memory or when the arrays hold INT_MAX points already. */
int particles_add(Particles *P, double x, double y, double m, double vol,
                  int mat, int body);

/** @brief Release the arrays. */
void particles_free(Particles *P);

/** @brief Bytes per point held by the arrays. */
double particles_bytes_per_point(void);

#endif
