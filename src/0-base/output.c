/**
 * @file output.c
 * @brief Writers for history, snapshots and CSV tables.
 */
#include "output.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "outfile.h"
#include "step.h"
#include "vtu_binary.h"

/** mkdir that is content when a directory of that name is there. */
static int make_one_dir(const char *path)
{
    struct stat st;
    if (mkdir(path, 0755) == 0)
        return 0;
    int err = errno;
    if (err == EEXIST && stat(path, &st) == 0 && S_ISDIR(st.st_mode))
        return 0;
    fprintf(stderr, "mpm: cannot create output directory %s: %s\n", path,
            strerror(err == EEXIST ? ENOTDIR : err));
    return -1;
}

int output_make_dir(const char *dir)
{
    char *path = malloc(strlen(dir) + 1);
    if (!path) {
        fprintf(stderr, "mpm: out of memory for the path %s\n", dir);
        return -1;
    }
    strcpy(path, dir);
    int rc = 0;
    for (char *c = path + 1; *c && rc == 0; c++) {
        if (*c != '/' || c[-1] == '/')
            continue;
        *c = '\0';
        rc = make_one_dir(path);
        *c = '/';
    }
    if (rc == 0)
        rc = make_one_dir(path);
    free(path);
    return rc;
}

void output_csv_time(const Sim *sim, FILE *f)
{
    fprintf(f, "# t = %.17g %s, step %ld\n", sim->t, sim->scene.run.units->time,
            sim->step);
}

/** The stages' columns of history.csv (SEAM_HISTORY, in order). */
static int history_columns(const Sim *sim, FILE *f, int header)
{
    const SeamList *l = &sim->hooks.seam[SEAM_HISTORY];
    int rc = 0;
    for (int k = 0; k < l->n; k++)
        rc |= l->at[k].fn.history(sim, l->at[k].state, f, header);
    return rc;
}

void output_history_header(const Sim *sim, FILE *f)
{
    fprintf(f, "step,time,kinetic,strain,total,momentum_x,momentum_y");
    for (int b = 0; b < sim->scene.nbodies; b++)
        fprintf(f, ",kinetic_%s", sim->scene.bodies[b].name);
    history_columns(sim, f, 1);
    fputc('\n', f);
}

Totals output_history_row(Sim *sim, FILE *f)
{
    Totals t = sim_totals(sim);
    const Particles *P = &sim->pts;
    memset(sim->bodyke, 0, (size_t)sim->scene.nbodies * sizeof(double));
    for (int p = 0; p < P->n; p++)
        sim->bodyke[P->body[p]] +=
            0.5 * P->m[p] * (P->vx[p] * P->vx[p] + P->vy[p] * P->vy[p]);
    int d = output_digits(sim, 10);
    fprintf(f, "%ld,%.*g,%.*g,%.*g,%.*g,%.*g,%.*g", sim->step, d, sim->t, d,
            t.kinetic, d, t.strain, d, t.kinetic + t.strain, d, t.px, d, t.py);
    for (int b = 0; b < sim->scene.nbodies; b++)
        fprintf(f, ",%.*g", d, sim->bodyke[b]);
    history_columns(sim, f, 0);
    fputc('\n', f);
    return t;
}

static void vtu_scalar(FILE *f, const char *name, const double *a, int n, int d)
{
    fprintf(f, "<DataArray type=\"Float64\" Name=\"%s\" format=\"ascii\">\n", name);
    for (int p = 0; p < n; p++)
        fprintf(f, "%.*g\n", d, a[p]);
    fprintf(f, "</DataArray>\n");
}

static void vtu_int(FILE *f, const char *name, const int *a, int n)
{
    fprintf(f, "<DataArray type=\"Int32\" Name=\"%s\" format=\"ascii\">\n", name);
    for (int p = 0; p < n; p++)
        fprintf(f, "%d\n", a[p]);
    fprintf(f, "</DataArray>\n");
}

/** The points as binary .vtu (run.output = "binary"), into @p name. */
static int write_vtu_binary(const Sim *sim, const char *dir, const char *name)
{
    const Particles *P = &sim->pts;
    const VtuArray a[] = {
        {"velocity", 3, P->vx, P->vy, NULL}, {"sigma_xx", 1, P->sxx, NULL, NULL},
        {"sigma_yy", 1, P->syy, NULL, NULL}, {"sigma_xy", 1, P->sxy, NULL, NULL},
        {"eps_xx", 1, P->exx, NULL, NULL},   {"eps_yy", 1, P->eyy, NULL, NULL},
        {"eps_xy", 1, P->exy, NULL, NULL},   {"mass", 1, P->m, NULL, NULL},
        {"material", 1, NULL, NULL, P->mat}, {"body", 1, NULL, NULL, P->body}};
    OutFile o;
    if (outfile_open(&o, dir, "%s", name))
        return -1;
    if (vtu_binary_write(o.f, sim->t, sim->step, P->n, P->x, P->y, a,
                         (int)(sizeof a / sizeof a[0]), "sigma_xx", "velocity")) {
        outfile_abandon(&o);
        return -1;
    }
    return outfile_commit(&o);
}

/// [write_vtu]
static int write_vtu(const Sim *sim, const char *dir, int index)
{
    const Particles *P = &sim->pts;
    if (sim->scene.run.binary) {
        char name[40];
        snprintf(name, sizeof name, "particles_%05d.vtu", index);
        return write_vtu_binary(sim, dir, name);
    }
    OutFile o;
    if (outfile_open(&o, dir, "particles_%05d.vtu", index))
        return -1;
    FILE *f = o.f;
    int n = P->n, d = output_digits(sim, 9), dx = output_digits(sim, 12);
    fprintf(f, "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" "
               "version=\"0.1\" byte_order=\"LittleEndian\">\n<UnstructuredGrid>\n"
               "<FieldData>\n<DataArray type=\"Float64\" Name=\"TimeValue\" "
               "NumberOfTuples=\"1\" format=\"ascii\">%.17g</DataArray>\n"
               "<DataArray type=\"Int64\" Name=\"step\" NumberOfTuples=\"1\" "
               "format=\"ascii\">%ld</DataArray>\n</FieldData>\n"
               "<Piece NumberOfPoints=\"%d\" NumberOfCells=\"%d\">\n<Points>\n"
               "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n",
            sim->t, sim->step, n, n);
    for (int p = 0; p < n; p++)
        fprintf(f, "%.*g %.*g 0\n", dx, P->x[p], dx, P->y[p]);
    fprintf(f, "</DataArray>\n</Points>\n<Cells>\n"
               "<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">\n");
    for (int p = 0; p < n; p++)
        fprintf(f, "%d\n", p);
    fprintf(f, "</DataArray>\n<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">\n");
    for (int p = 0; p < n; p++)
        fprintf(f, "%d\n", p + 1);
    fprintf(f, "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n");
    for (int p = 0; p < n; p++)
        fprintf(f, "1\n");                              /* VTK_VERTEX */
    fprintf(f, "</DataArray>\n</Cells>\n<PointData Scalars=\"sigma_xx\" Vectors=\"velocity\">\n"
               "<DataArray type=\"Float64\" Name=\"velocity\" NumberOfComponents=\"3\" "
               "format=\"ascii\">\n");
    for (int p = 0; p < n; p++)
        fprintf(f, "%.*g %.*g 0\n", d, P->vx[p], d, P->vy[p]);
    fprintf(f, "</DataArray>\n");
    vtu_scalar(f, "sigma_xx", P->sxx, n, d);
    vtu_scalar(f, "sigma_yy", P->syy, n, d);
    vtu_scalar(f, "sigma_xy", P->sxy, n, d);
    vtu_scalar(f, "eps_xx", P->exx, n, d);
    vtu_scalar(f, "eps_yy", P->eyy, n, d);
    vtu_scalar(f, "eps_xy", P->exy, n, d);
    vtu_scalar(f, "mass", P->m, n, d);
    vtu_int(f, "material", P->mat, n);
    vtu_int(f, "body", P->body, n);
    fprintf(f, "</PointData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n");
    return outfile_commit(&o);
}
/// [write_vtu]

/** The nodes that carry mass, as binary .vtu: the grid's scratch arrays
 *  (free between steps) are packed in place, node order kept. */
static int write_grid_binary(Sim *sim, const char *dir, const char *name)
{
    Grid *g = &sim->grid;
    int k = 0;
    for (int n = 0; n < g->nnodes; n++) {
        if (g->m[n] <= 0)
            continue;
        double im = 1.0 / g->m[n];
        g->vx[k] = grid_node_x(g, n);
        g->vy[k] = grid_node_y(g, n);
        g->ax[k] = g->fx[n] * im;                  /* k <= n: in place */
        g->ay[k] = g->fy[n] * im;
        g->px[k] = g->px[n] * im;
        g->m[k++] = g->m[n];
    }
    const VtuArray a[] = {{"mass", 1, g->m, NULL, NULL},
        {"sigma_xx", 1, g->ax, NULL, NULL}, {"sigma_yy", 1, g->ay, NULL, NULL},
        {"sigma_xy", 1, g->px, NULL, NULL}};
    OutFile o;
    int rc = outfile_open(&o, dir, "%s", name);
    if (rc == 0 && vtu_binary_write(o.f, sim->t, sim->step, k, g->vx, g->vy, a,
                                    4, "sigma_xx", NULL)) {
        outfile_abandon(&o);
        rc = -1;
    } else if (rc == 0) {
        rc = outfile_commit(&o);
    }
    grid_clear(g, sim->threads);
    return rc;
}

int output_grid_csv(Sim *sim, const char *dir, const char *name)
{
    Grid *g = &sim->grid;
    const Particles *P = &sim->pts;
    size_t bytes = (size_t)g->nnodes * sizeof(double);
    /* between steps the grid arrays are free scratch space (Task 8) */
    memset(g->m, 0, bytes);
    memset(g->fx, 0, bytes);
    memset(g->fy, 0, bytes);
    memset(g->px, 0, bytes);
    for (int p = 0; p < P->n; p++) {
        Stencil st;                      /* all fields of a node together */
        stencil_at(g, P->x[p], P->y[p], &st);
        for (int a = 0; a < STENCIL_NODES; a++) {
            int n = st.slot[a];
            double w = P->m[p] * st.S[a];
            g->m[n] += w;
            g->fx[n] += w * P->sxx[p];
            g->fy[n] += w * P->syy[p];
            g->px[n] += w * P->sxy[p];
        }
    }
    if (sim->scene.run.binary)
        return write_grid_binary(sim, dir, name);
    OutFile o;
    if (outfile_open(&o, dir, "%s", name)) {
        grid_clear(g, sim->threads);
        return -1;
    }
    FILE *f = o.f;
    int d = output_digits(sim, 10);
    output_csv_time(sim, f);
    fprintf(f, "x,y,mass,sigma_xx,sigma_yy,sigma_xy\n");
    for (int n = 0; n < g->nnodes; n++) {
        if (g->m[n] <= 0)
            continue;
        double im = 1.0 / g->m[n];
        fprintf(f, "%.*g,%.*g,%.*g,%.*g,%.*g,%.*g\n", d, grid_node_x(g, n),
                d, grid_node_y(g, n), d, g->m[n], d, g->fx[n] * im,
                d, g->fy[n] * im, d, g->px[n] * im);
    }
    grid_clear(g, sim->threads);
    return outfile_commit(&o);
}

int output_points_final(const Sim *sim, const char *dir)
{
    return sim->scene.run.binary
               ? write_vtu_binary(sim, dir, "particles_final.vtu")
               : output_points_csv(sim, dir, "particles_final.csv");
}

int output_points_csv(const Sim *sim, const char *dir, const char *name)
{
    const Particles *P = &sim->pts;
    OutFile o;
    if (outfile_open(&o, dir, "%s", name))
        return -1;
    FILE *f = o.f;
    output_csv_time(sim, f);
    fprintf(f, "x,y,vx,vy,sigma_xx,sigma_yy,sigma_xy,eps_xx,eps_yy,eps_xy,"
               "mass,material,body\n");
    int d = output_digits(sim, 10), dx = output_digits(sim, 12);
    for (int p = 0; p < P->n; p++)
        fprintf(f, "%.*g,%.*g,%.*g,%.*g,%.*g,%.*g,%.*g,%.*g,%.*g,%.*g,%.*g,%d,%d\n",
                dx, P->x[p], dx, P->y[p], d, P->vx[p], d, P->vy[p], d, P->sxx[p],
                d, P->syy[p], d, P->sxy[p], d, P->exx[p], d, P->eyy[p],
                d, P->exy[p], d, P->m[p], P->mat[p], P->body[p]);
    return outfile_commit(&o);
}

int output_series(const Sim *sim, const char *dir, const char *name,
                  const char *stem, const char *ext, int index,
                  const double *times)
{
    OutFile o;
    if (outfile_open(&o, dir, "%s", name))
        return -1;
    fprintf(o.f, "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n"
                 "<Collection>\n");
    for (int k = 0; k <= index; k++)
        fprintf(o.f, "<DataSet timestep=\"%.*g\" file=\"%s_%05d.%s\"/>\n",
                output_digits(sim, 10), times[k], stem, k, ext);
    fprintf(o.f, "</Collection>\n</VTKFile>\n");
    return outfile_commit(&o);
}

int output_snapshot(Sim *sim, const char *dir, int index, const double *times)
{
    char name[32];
    snprintf(name, sizeof name, "grid_%05d.%s", index,
             sim->scene.run.binary ? "vtu" : "csv");
    if (write_vtu(sim, dir, index) || output_grid_csv(sim, dir, name))
        return -1;
    const SeamList *l = &sim->hooks.seam[SEAM_SNAPSHOT];
    for (int k = 0; k < l->n; k++)
        if (l->at[k].fn.snapshot(sim, l->at[k].state, dir, index, times))
            return -1;
    /* rewrite the series so that it is complete after every snapshot */
    if (sim->scene.run.binary &&
        output_series(sim, dir, "grid.pvd", "grid", "vtu", index, times))
        return -1;
    return output_series(sim, dir, "particles.pvd", "particles", "vtu", index,
                         times);
}
