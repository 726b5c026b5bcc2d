/**
 * @file crack_output.c
 * @brief Cracks in the output: a ParaView polyline file (listed in the
 *        series cracks.pvd) and a CSV per snapshot, and the multi-field
 *        node count in history.csv.
 */
#include <stdio.h>

#include "cracks.h"
#include "outfile.h"
#include "output.h"

/// [cracks_snapshot]
int cracks_snapshot(const Sim *sim, void *state, const char *dir, int index,
                    const double *times)
{
    const Cracks *C = state;
    int d = output_digits(sim, 12);
    OutFile o;
    if (outfile_open(&o, dir, "cracks_%05d.csv", index))
        return -1;
    FILE *f = o.f;
    output_csv_time(sim, f);
    fprintf(f, "crack,point,x,y\n");
    for (int k = 0; k < C->ncracks; k++)
        for (int j = 0; j < C->crack[k].n; j++)
            fprintf(f, "%d,%d,%.*g,%.*g\n", k, j, d, C->crack[k].x[j], d,
                    C->crack[k].y[j]);
    if (outfile_commit(&o) || outfile_open(&o, dir, "cracks_%05d.vtp", index))
        return -1;
    f = o.f;
    int npts = 0;
    for (int k = 0; k < C->ncracks; k++)
        npts += C->crack[k].n;
    fprintf(f, "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" "
               "byte_order=\"LittleEndian\">\n<PolyData>\n<Piece NumberOfPoints=\"%d\" "
               "NumberOfLines=\"%d\">\n<Points>\n<DataArray type=\"Float64\" "
               "NumberOfComponents=\"3\" format=\"ascii\">\n", npts, C->ncracks);
    for (int k = 0; k < C->ncracks; k++)
        for (int j = 0; j < C->crack[k].n; j++)
            fprintf(f, "%.*g %.*g 0\n", d, C->crack[k].x[j], d, C->crack[k].y[j]);
    fprintf(f, "</DataArray>\n</Points>\n<Lines>\n<DataArray type=\"Int32\" "
               "Name=\"connectivity\" format=\"ascii\">\n");
    for (int j = 0; j < npts; j++)
        fprintf(f, "%d\n", j);
    fprintf(f, "</DataArray>\n<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">\n");
    for (int k = 0, off = 0; k < C->ncracks; k++) {
        off += C->crack[k].n;
        fprintf(f, "%d\n", off);
    }
    fprintf(f, "</DataArray>\n</Lines>\n</Piece>\n</PolyData>\n</VTKFile>\n");
    if (outfile_commit(&o))
        return -1;
    /* the crack lines as one series in time, beside particles.pvd */
    return output_series(sim, dir, "cracks.pvd", "cracks", "vtp", index, times);
}
/// [cracks_snapshot]

int cracks_history(const Sim *sim, void *state, FILE *f, int header)
{
    (void)state;
    if (header)
        return fprintf(f, ",multi_field_nodes") < 0 ? -1 : 0;
    return fprintf(f, ",%d", cracks_multi_field_nodes(sim)) < 0 ? -1 : 0;
}
