/*
 * surfaceNodes.c — wall nodes ON a circle, for the MLPG_R solver (Pan 2022
 * thesis sect. 4.3.3: the cylinder carries n nodes at spacing 2 pi R/n):
 * a wall region with `surfaceNodes yes` gets n = round(2 pi R/dp) nodes
 * at equal angles on its circle instead of its lattice sites, with the
 * normal from the fluid into the solid (as every wall particle), and the
 * fluid sites closer to the circle than surfaceClearance dp (default 0.5)
 * are dropped, so that no fluid node crowds a wall node.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/dict.h"
#include "core/error.h"
#include "core/log.h"
#include "genParticles.h"

/* Keep particle k (copy it to slot n). */
static void keep(struct mps_cloud *m, size_t k, size_t n)
{
    memmove(m->x + 3 * n, m->x + 3 * k, 3 * sizeof *m->x);
    memmove(m->u + 3 * n, m->u + 3 * k, 3 * sizeof *m->u);
    memmove(m->normal + 3 * n, m->normal + 3 * k, 3 * sizeof *m->normal);
    m->p[n] = m->p[k];
    m->type[n] = m->type[k];
    m->patch[n] = m->patch[k];
    m->region[n] = m->region[k];
    if (m->phase)
        m->phase[n] = m->phase[k];
}

static int grow(struct mps_cloud *m, size_t n)
{
    SIM_GROW(m->x, 3 * n);
    SIM_GROW(m->u, 3 * n);
    SIM_GROW(m->normal, 3 * n);
    SIM_GROW(m->p, n);
    SIM_GROW(m->type, n);
    SIM_GROW(m->patch, n);
    SIM_GROW(m->region, n);
    if (m->phase)
        SIM_GROW(m->phase, n);
    return SIM_OK;
}

int gen_surface_nodes(struct gen_case *c, struct mps_cloud *m)
{
    for (int i = 0; i < c->nregions; i++) {
        struct region *r = &c->r[i];
        if (!r->surface_nodes)
            continue;
        const double R = r->g.radius, *o = r->g.p;
        size_t n = 0, dropped = 0;
        for (size_t k = 0; k < m->n; k++) {
            double d = geom_distance(&r->g, m->x + 3 * k);
            int mine = m->region[k] == i;
            int close = m->type[k] == TYPE_FLUID && d < r->clearance * c->dp;
            if (mine || close) {
                dropped += close;
                continue;
            }
            keep(m, k, n++);
        }
        long nodes = lround(2 * M_PI * R / c->dp);
        if (nodes < 8)
            return dict_error(r->d, "radius", SIM_ERR_DICT, "region '%s': "
                              "%ld nodes on the circle (2 pi R/dp): at least "
                              "8 are needed", r->name, nodes);
        TRY(grow(m, n + (size_t)nodes));
        for (long q = 0; q < nodes; q++, n++) {
            double a = 2 * M_PI * (double)q / (double)nodes;
            double e[3] = { cos(a), sin(a), 0 };
            for (int d = 0; d < 3; d++) {
                m->x[3 * n + d] = o[d] + R * e[d];
                m->u[3 * n + d] = 0;
                m->normal[3 * n + d] = -e[d]; /* into the solid */
            }
            m->x[3 * n + 2] = 0;
            m->p[n] = 0;
            m->type[n] = TYPE_WALL;
            m->patch[n] = m->region[n] = i;
            if (m->phase)
                m->phase[n] = 0;
        }
        m->n = n;
        log_info("Region %s: %ld nodes on its circle (spacing %g m); %zu "
                 "fluid sites within %g dp of it dropped", r->name, nodes,
                 2 * M_PI * R / (double)nodes, dropped, r->clearance);
    }
    /* the counts of the summary */
    for (int i = 0; i < c->nregions; i++)
        if (c->r[i].type != REGION_GRAINS)
            memset(c->r[i].count, 0, 3 * sizeof c->r[i].count[0]);
    for (size_t k = 0; k < m->n; k++)
        c->r[m->region[k]].count[m->type[k]]++;
    return SIM_OK;
}
