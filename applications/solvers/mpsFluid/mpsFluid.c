/*
 * mpsFluid — incompressible MPS solver for free-surface flows (Xie et al.
 * 2025 with eps = 1; doc/theory.md A.2-A.5, A.9, A.10; doc/design.md §5).
 *
 * Reads   system/controlDict, system/mpsSchemes, system/mpsSolution,
 *         constant/transportProperties, constant/particlePatches
 *         (from genParticles: patch names, dimension, dp), constant/g
 *         (optional: a missing file is a logged default),
 *         system/particleDict (optional: the motion and removeAt of its
 *         wall regions, matched to the patches by name),
 *         <startTime>/fluid.vtu
 * Writes  <time>/fluid.vtu, fluid.pvd, postProcessing/<functionObject>/,
 *         postProcessing/usedParameters/mpsFluid
 *
 * With -parallel (MPI build; doc/design.md §8) the ranks share the
 * particles (particles/distribute.h, mps_halo.c) and each time holds
 * <time>/fluid.pvtu with one piece fluid_<rank>.vtu per rank.
 *
 * Every key: mpsFluid.reference beside this file.
 *
 * Coupled (system/couplingDict present, `coupled yes`; runTandem mpsFluid
 * demSolid): before each step the fluid state at the grains is sent and the
 * DEM state at the end of the step received; porosity and the reaction of
 * the grains enter the step through the solver's inv_eps and f_ext hooks
 * (couple_fluid.h). Output gains the fields "porosity" and "reaction"
 * (-V_i f_A,i of eq. 36, couple_fluid_reaction_field). With -parallel,
 * rank 0 holds the channel and shares the grains with the other ranks.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/dict.h"
#include "core/error.h"
#include "core/gravity.h"
#include "core/log.h"
#include "couplingMps/couple_fluid.h"
#include "coupling/models.h"
#include "functionObjects/functionObject.h"
#include "io/vtu.h"
#include "functionObjects/mps_functionObjects.h"
#include "mps/mps.h"
#include "mps/soil/soil.h"
#include "solver/solver.h"
#ifdef MPSDEM_HAVE_MPI
#include "particles/decompose.h"
#include "particles/distribute.h"
#endif

#define MAX_PATCHES 64

struct fluid {
    struct solver sv;               /* first: the hooks cast back        */
    struct dict *transport, *gravity, *schemes, *solution, *patches;
    struct dict *particles;         /* system/particleDict, or NULL      */
    struct dict *soil_dict;         /* constant/soilProperties, or NULL  */
    struct soil_props soil;         /* read when the particles hold soil */
    struct wall_motion motion[MAX_PATCHES];
    struct mps_solver s;
    int dim;
    double dp;
    int npatches;
    const char *patch_names[MAX_PATCHES];
    char value_names[MAX_PATCHES + 2][80];
    struct fo_value values[MAX_PATCHES + 2];
    double force[3 * MAX_PATCHES];
    struct vtu_cloud cloud;         /* fluid.vtu: a view of s.P.st      */
    struct vtu_field fields[STORE_MAX_FIELDS];
    struct couple_fluid cf;         /* coupled runs only                 */
    double *porosity, *reaction;    /* their fields of the store: eps_i,
                                       -V_i f_A,i of the last exchange,
                                       kept through renumbering and
                                       migration                        */
#ifdef MPSDEM_HAVE_MPI
    struct dist *dist;              /* -parallel: this rank's part       */
#endif
    const struct store *whole;      /* the cloud written and measured:
                                       s.P.st, or with -parallel the
                                       gathered one (rank 0; else NULL) */
};

/* constant/particlePatches: patch names, dimension and dp of the lattice. */
static int read_patches(struct fluid *f)
{
    return solver_read_patches(&f->sv, 0, &f->patches, &f->dim, &f->dp,
                               f->patch_names, MAX_PATCHES, &f->npatches);
}

/* The region of system/particleDict that made patch `name`: a list item
 * name { ... } or an entry of a regions { } dictionary. */
static int find_region(const struct dict *pd, const char *name,
                       const struct dict **out)
{
    *out = NULL;
    if (dict_is_dict(pd, "regions")) {
        const struct dict *rd;
        TRY(dict_get_dict(pd, "regions", &rd));
        return dict_find_dict(rd, name, out);
    }
    const struct dict_value *l;
    TRY(dict_get_list(pd, "regions", &l));
    for (int i = 0; i + 1 < dict_value_len(l); i += 2) {
        const struct dict_value *v = dict_value_at(l, i);
        const struct dict_value *b = dict_value_at(l, i + 1);
        if (dict_value_kind(v) == DICT_WORD
            && strcmp(dict_value_text(v), name) == 0
            && dict_value_kind(b) == DICT_DICT) {
            *out = dict_value_dict(b);
            break;
        }
    }
    return SIM_OK;
}

/* Motion and removeAt of the wall patches (system/particleDict, the file
 * genParticles and demSolid read too, so that the walls agree). */
static int read_motions(struct fluid *f, struct mps_settings *S)
{
    for (int k = 0; k < MAX_PATCHES; k++)
        wall_motion_init(&f->motion[k]);
    TRY(app_read_dict_optional(&f->sv.app, "system/particleDict",
                               &f->particles));
    if (!f->particles)
        return SIM_OK;
    for (int k = 0; k < f->npatches; k++) {
        const struct dict *r;
        TRY(find_region(f->particles, f->patch_names[k], &r));
        if (!r)
            continue;
        const char *type;
        TRY(dict_get_string(r, "type", &type));
        int is_wall = !strcmp(type, "wall") || !strcmp(type, "tankWall");
        TRY(wall_motion_read(r, is_wall, f->dim, f->sv.app.case_abs,
                             &f->motion[k]));
        struct wall_motion *m = &f->motion[k];
        if (wall_motion_moves(m))
            log_info("Patch %s moves (motion %s)", f->patch_names[k],
                     m->ops->name);
        if (isfinite(m->remove_at))
            log_info("Patch %s is removed at t = %g s", f->patch_names[k],
                     m->remove_at);
    }
    S->wall_motion = f->motion;
    S->n_wall_motion = f->npatches;
    return SIM_OK;
}

/* Optional field volumeFraction (genParticles grainVolume scale): the
 * fluid volume of each particle in units of dp^d, in (0, 1]. Only a
 * coupled run knows the porosity it compensates. */
static int copy_volume_fraction(const struct vtu_cloud *c, const char *path,
                                struct mps_particles *P)
{
    const struct vtu_field *vf = vtu_find(c, "volumeFraction");
    if (!vf)
        return SIM_OK;
    if (vf->type != VTU_FLOAT64 || vf->ncomp != 1)
        return sim_error(SIM_ERR_INPUT, "%s: field 'volumeFraction' must be "
                         "Float64 with one component", path);
    const double *v = vf->data;
    TRY(mps_particles_add(P, MPS_P_PHI));
    for (size_t i = 0; i < c->n; i++) {
        if (!(v[i] > 0 && v[i] <= 1))
            return sim_error(SIM_ERR_INPUT, "%s: particle %zu has "
                             "volumeFraction %g (must lie in (0, 1])", path,
                             i, v[i]);
        P->phi[i] = v[i];
    }
    return SIM_OK;
}

/* Optional fields phase (genParticles soil regions: 1 soil, 0 the others)
 * and acceleration (the last step's, written by a soil run: its restart
 * goes on with it). Returns in *nsoil the soil particles. */
static int copy_soil(const struct vtu_cloud *c, const char *path,
                     struct mps_particles *P, int *nsoil)
{
    const struct vtu_field *ph = vtu_find(c, "phase"), *ac;
    *nsoil = 0;
    if (!ph)
        return SIM_OK;
    TRY(vtu_require(c, path, "phase", VTU_INT32, 1, &ph));
    TRY(mps_particles_add(P, MPS_P_SOIL));
    const int32_t *v = ph->data;
    for (size_t i = 0; i < c->n; i++) {
        if (v[i] != 0 && v[i] != 1)
            return sim_error(SIM_ERR_INPUT, "%s: particle %zu has phase %d "
                             "(1 soil, 0 the others)", path, i, (int)v[i]);
        if (v[i] == 1 && P->type[i] != MPS_FLUID)
            return sim_error(SIM_ERR_INPUT, "%s: particle %zu is a wall or "
                             "dummy particle (type %d) with phase 1 (soil)",
                             path, i, (int)P->type[i]);
        P->phase[i] = v[i];
        *nsoil += v[i] == 1;
    }
    ac = vtu_find(c, "acceleration");
    if (ac) {
        TRY(vtu_require(c, path, "acceleration", VTU_FLOAT64, 3, &ac));
        memcpy(P->accel, ac->data, sizeof *P->accel * 3 * c->n);
    }
    return SIM_OK;
}

/* constant/soilProperties: required when the particles hold soil, and
 * then the soil model of the run; a file without soil particles is
 * reported and not read. */
static int read_soil(struct fluid *f, int nsoil, struct mps_settings *S)
{
    char path[4400];
    app_path(&f->sv.app, "constant/soilProperties", path, sizeof path);
    int exists = access(path, R_OK) == 0;
    if (!nsoil) {
        if (exists)
            log_warn("constant/soilProperties is not used: the particles "
                     "hold no soil (genParticles regions of type soil)");
        return SIM_OK;
    }
    if (!exists)
        return sim_error(SIM_ERR_INPUT, "%s: missing: the particles hold %d "
                         "soil particles (field 'phase' of the start state), "
                         "whose model and density this file gives "
                         "(doc/theory.md K)", path, nsoil);
    TRY(app_read_dict(&f->sv.app, "constant/soilProperties", &f->soil_dict));
    TRY(soil_props_read(f->soil_dict, &f->soil));
    S->soil = &f->soil;
    log_info("Soil: %d particles, model %s, rho %g kg/m^3", nsoil,
             soil_model_table[f->soil.model]->name, f->soil.rho);
    return SIM_OK;
}

static int copy_cloud(struct fluid *f, const struct vtu_cloud *c,
                      const char *path, struct mps_particles *P, int *nsoil)
{
    const struct vtu_field *ty, *pa, *ve, *pr, *no, *id;
    TRY(vtu_require(c, path, "type", VTU_INT32, 1, &ty));
    TRY(vtu_require(c, path, "patch", VTU_INT32, 1, &pa));
    TRY(vtu_require(c, path, "velocity", VTU_FLOAT64, 3, &ve));
    TRY(vtu_require(c, path, "pressure", VTU_FLOAT64, 1, &pr));
    TRY(vtu_require(c, path, "normal", VTU_FLOAT64, 3, &no));
    id = vtu_find(c, "id");
    if (id && (id->type != VTU_INT64 || id->ncomp != 1))
        return sim_error(SIM_ERR_INPUT, "%s: field 'id' must be Int64", path);
    if (c->n > 2000000000)
        return sim_error(SIM_ERR_INPUT, "%s: too many particles", path);
    int n = (int)c->n;
    TRY(mps_particles_alloc(P, n, f->dim));
    if (f->sv.coupled) {
        /* the coupling's fields of fluid.vtu (porosity filled when
         * written, reaction at each exchange); registered before
         * volumeFraction, which follows them */
        TRY(store_add(&P->st, "porosity", "eps", VTU_FLOAT64, 1,
                      STORE_WRITE, &f->porosity));
        TRY(store_add(&P->st, "reaction", "-V_i f_A,i of eq. (36) [N]",
                      VTU_FLOAT64, 3, STORE_WRITE, &f->reaction));
    }
    memcpy(P->x, c->points, sizeof *P->x * 3 * n);
    memcpy(P->u, ve->data, sizeof *P->u * 3 * n);
    memcpy(P->p, pr->data, sizeof *P->p * n);
    memcpy(P->normal, no->data, sizeof *P->normal * 3 * n);
    memcpy(P->type, ty->data, sizeof *P->type * n);
    memcpy(P->patch, pa->data, sizeof *P->patch * n);
    if (id)
        memcpy(P->id, id->data, sizeof *P->id * n);
    TRY(copy_volume_fraction(c, path, P));
    TRY(copy_soil(c, path, P, nsoil));
    for (int i = 0; i < n; i++) {
        if (P->type[i] < 0 || P->type[i] > 2)
            return sim_error(SIM_ERR_INPUT, "%s: particle %d has type %d "
                             "(0 fluid, 1 wall, 2 dummy)", path, i,
                             P->type[i]);
        if (P->patch[i] >= f->npatches)
            return sim_error(SIM_ERR_INPUT, "%s: particle %d has patch %d "
                             "but constant/particlePatches lists %d", path,
                             i, P->patch[i], f->npatches);
        if (f->dim == 2 && P->x[3 * i + 2] != 0)
            return sim_error(SIM_ERR_INPUT, "%s: 2-D case but particle %d "
                             "has z = %g", path, i, P->x[3 * i + 2]);
        for (int q = 0; q < 3; q++)
            if (!isfinite(P->x[3 * i + q]) || !isfinite(P->u[3 * i + q]))
                return sim_error(SIM_ERR_INPUT, "%s: particle %d has a "
                                 "non-finite position or velocity", path, i);
    }
    return SIM_OK;
}

/* system/couplingDict: nothing of the grains exists without it. */
static int create_coupling(struct fluid *f)
{
    if (!f->sv.coupled)
        return SIM_OK;
    if (f->sv.rt.adjust)
        return dict_error(f->sv.control, "adjustTimeStep", SIM_ERR_DICT,
                          "a coupled run needs a fixed deltaT, the same as "
                          "demSolid's (the coupling interval): set "
                          "adjustTimeStep no");
    return couple_fluid_init(&f->cf, f->sv.coupling, &f->s);
}

static int create_fluid(struct fluid *f)
{
    char rel[256], path[4400];
    struct mps_settings S;
    struct mps_particles P;
    double g[3];
    struct vtu_cloud c = { 0 };
    struct linsolve *ls = NULL;
    const struct dict *ppe;
    int rc, nsoil = 0;

    TRY(read_patches(f));
    TRY(app_read_dict(&f->sv.app, "constant/transportProperties",
                      &f->transport));
    TRY(gravity_case(&f->sv.app, f->dim, g, &f->gravity));
    TRY(app_read_dict(&f->sv.app, "system/mpsSchemes", &f->schemes));
    TRY(app_read_dict(&f->sv.app, "system/mpsSolution", &f->solution));
    TRY(mps_settings_read(f->transport, NULL, f->schemes, f->solution, &S));
    memcpy(S.g, g, sizeof S.g);
    TRY(read_motions(f, &S));
    if (f->gravity && f->dim == 2 && S.g[2] != 0)
        return dict_error(f->gravity, dict_has(f->gravity, "value") ? "value"
                          : "g", SIM_ERR_DICT, "2-D case: gravity must lie "
                          "in the x-y plane, e.g. (0 -9.81 0)");
    TRY(dict_get_dict(f->solution, "PPE", &ppe));
    TRY(linsolve_create(ppe, &ls));
    /* the whole cloud, or the pieces of a distributed run */
    snprintf(rel, sizeof rel, "%s/fluid.pvtu", f->sv.rt.name);
    app_path(&f->sv.app, rel, path, sizeof path);
    if (access(path, F_OK) != 0) {
        snprintf(rel, sizeof rel, "%s/fluid.vtu", f->sv.rt.name);
        app_path(&f->sv.app, rel, path, sizeof path);
    }
    rc = vtu_read(path, &c);
    if (!rc)
        rc = vtu_check_finite(&c, path);
    if (!rc)
        rc = copy_cloud(f, &c, path, &P, &nsoil);
    vtu_cloud_free(&c);
    if (!rc && (rc = read_soil(f, nsoil, &S)) != SIM_OK)
        mps_particles_free(&P);
    if (!rc && (rc = mps_check_extent(&P, &S, f->dp, path)) != SIM_OK)
        mps_particles_free(&P);
    if (rc) {
        linsolve_free(ls);
        return rc;
    }
    log_info("Fluid cloud %s: %d particles, %d-D, dp = %g m", rel, P.n,
             f->dim, f->dp);
    TRY(mps_solver_init(&f->s, &P, &S, f->dp, ls));
    f->s.time = f->sv.rt.value;
    TRY(create_coupling(f));
    if (f->s.P.phi && !f->sv.coupled)
        return sim_error(SIM_ERR_INPUT, "%s: field 'volumeFraction' (fluid "
                         "displaced by grains: genParticles grainVolume "
                         "scale) needs a coupled run (system/couplingDict: "
                         "coupled yes)", path);
    return mps_check_setup(&f->s, f->sv.rt.delta_t, f->sv.rt.adjust,
                           f->sv.rt.adjust ? f->sv.rt.max_co : 0.2);
}

#ifdef MPSDEM_HAVE_MPI
static int halo_solve(struct pop_halo *h, struct linsolve *ls,
                      const struct csr_matrix *A, int64_t row0,
                      int64_t nglobal, const double *b, double *x,
                      struct linsolve_stats *st)
{
    return linsolve_solve_dist(ls, dist_comm(h), A, row0, nglobal, b, x, st);
}

/* -parallel: every rank read the whole start cloud and set the solver up
 * on it; each keeps its region's particles and the ghosts (doc/design.md
 * §8). system/decomposeParDict, when the case has one, gives what is
 * balanced and when the regions are cut afresh (decompose.h); its
 * numberOfSubdomains is mpirun's -np, as for OpenFOAM's solvers. */
static int distribute(struct fluid *f)
{
    struct decompose_settings ds = { .nparts = 0, .balance_all = 0,
                                     .max_imbalance = 1.2 };
    struct dict *dec = NULL;
    TRY(app_read_dict_optional(&f->sv.app, "system/decomposeParDict", &dec));
    int rc = dec ? decompose_settings_read(dec, &ds) : SIM_OK;
    int nranks;
    MPI_Comm_size(MPI_COMM_WORLD, &nranks);
    if (!rc && dec && ds.nparts != nranks)
        log_warn("system/decomposeParDict: numberOfSubdomains %ld, but the "
                 "run has %d ranks (mpirun -np): the particles are cut in "
                 "%d", ds.nparts, nranks, nranks);
    dict_free(dec);
    TRY(rc);
    struct mps_particles *P = &f->s.P;
    double *w = sim_malloc(((size_t)P->n + 1) * sizeof *w);
    if (!w)
        return SIM_ERR_NOMEM;
    mps_balance_weights(P, P->n, ds.balance_all, w);
    rc = mps_halo_reach(&f->s);
    if (!rc)
        rc = dist_create(MPI_COMM_WORLD, f->dim, f->s.r_list, &f->dist);
    if (!rc) {
        dist_set_solve(f->dist, halo_solve);
        rc = dist_split(f->dist, &P->st, w);
    }
    free(w);
    TRY(rc);
    struct pop_halo *h = dist_halo(f->dist);
    h->max_imbalance = ds.max_imbalance;
    h->balance_all = ds.balance_all;
    TRY(mps_distribute(&f->s, h, f->schemes));
    log_info("Distributed over %d ranks (balance %s, maxImbalance %g): rank "
             "0 owns %d particles and holds %d ghosts within %g m", h->size,
             ds.balance_all ? "all" : "fluid", ds.max_imbalance, h->n_own,
             P->n - h->n_own, f->s.r_list);
    return SIM_OK;
}
#endif

/* The cloud of the output and the function objects: with -parallel, the
 * ranks' own particles gathered on rank 0 (collective). */
static int whole_cloud(struct fluid *f)
{
#ifdef MPSDEM_HAVE_MPI
    if (f->dist) {
        struct store *w;
        TRY(dist_gather(f->dist, &f->s.P.st, &w));
        f->whole = w;
        struct pop_halo *h = dist_halo(f->dist);
        h->ops->reduce(h, f->force, 3 * f->npatches, POP_SUM);
        return SIM_OK;
    }
#endif
    f->whole = &f->s.P.st;
    return SIM_OK;
}

/* The porosity field of the output (coupled runs). */
static void porosity_field(struct fluid *f)
{
    const struct mps_particles *P = &f->s.P;
    if (!f->sv.coupled)
        return;
    /* inv_eps holds phi_i/eps_i with volume fractions */
    for (int i = 0; i < P->n; i++)
        f->porosity[i] = (P->phi ? P->phi[i] : 1.0) / P->inv_eps[i];
}

static int refresh_scene(struct solver *sv)
{
    struct fluid *f = (struct fluid *)sv;
    porosity_field(f);
    mps_wall_forces(&f->s, f->npatches, f->force);
    TRY(whole_cloud(f));
    if (!f->whole)
        return SIM_OK;    /* a rank other than 0 of a distributed run */
    store_cloud(f->whole, f->sv.rt.value, f->fields, &f->cloud);
    int nv = 0;
    for (int k = 0; k < f->npatches; k++, nv++) {
        snprintf(f->value_names[nv], sizeof f->value_names[nv],
                 "wallForce.%s", f->patch_names[k]);
        f->values[nv] = (struct fo_value){ .name = f->value_names[nv],
                                           .ncomp = 3 };
        memcpy(f->values[nv].v, f->force + 3 * k, 3 * sizeof(double));
    }
    f->values[nv++] = (struct fo_value){ .name = "escaped", .ncomp = 1,
                                         .v = { (double)f->s.n_escaped } };
    f->values[nv++] = (struct fo_value){ .name = "n0", .ncomp = 1,
                                         .v = { f->s.Ln.n0 } };
    f->sv.scene = (struct fo_scene){
        .time = f->sv.rt.value, .dt = f->sv.rt.dt, .step = f->sv.rt.step,
        .dim = f->dim, .cloud_name = "fluid", .store = f->whole,
        .spacing = f->dp, .patch_names = f->patch_names,
        .npatches = f->npatches, .values = f->values, .nvalues = nv,
        .solver = &f->s };
    return SIM_OK;
}

static int create(struct solver *sv)
{
    struct fluid *f = (struct fluid *)sv;
    TRY(create_fluid(f));
#ifdef MPSDEM_HAVE_MPI
    if (sv->distributed)
        TRY(distribute(f));
#endif
    TRY(solver_check_unused(sv, f->schemes));
    TRY(solver_check_unused(sv, f->solution));
    return solver_check_unused(sv, f->transport);
}

/* fluid.vtu into dir: the time directory or failed.<t>/. */
#ifdef MPSDEM_HAVE_MPI
/* A distributed run writes its own particles as piece <rank> of
 * <dir>/fluid.pvtu (doc/design.md §8); the ranks agree on the outcome. */
static int write_pieces(struct fluid *f, const char *dir)
{
    struct pop_halo *h = dist_halo(f->dist);
    struct vtu_cloud piece;
    char path[4400];
    porosity_field(f);
    store_cloud(&f->s.P.st, f->sv.rt.value, f->fields, &piece);
    piece.n = (size_t)h->n_own;       /* own particles come first */
    snprintf(path, sizeof path, "%s/fluid_%d.vtu", dir, h->rank);
    int rc = vtu_write(path, &piece, f->sv.rt.binary);
    if (!rc && h->rank == 0) {
        snprintf(path, sizeof path, "%s/fluid.pvtu", dir);
        rc = pvtu_write(path, &piece, h->size, "fluid_%d.vtu");
        snprintf(path, sizeof path, "%s/fluid.vtu", dir);
        unlink(path);                 /* a whole cloud of an earlier run */
    }
    if (pop_halo_reduce1(h, rc != SIM_OK, POP_MAX) > 0 && !rc)
        rc = sim_error(SIM_ERR_IO, "%s: another rank could not write its "
                       "piece of fluid.pvtu", dir);
    return rc;
}
#endif

static int write_fields(struct solver *sv, const char *dir)
{
    struct fluid *f = (struct fluid *)sv;
    char path[4400];
#ifdef MPSDEM_HAVE_MPI
    if (f->dist)
        return write_pieces(f, dir);
#endif
    TRY(refresh_scene(sv));
    snprintf(path, sizeof path, "%s/fluid.pvtu", dir);
    unlink(path);                     /* the pieces of an earlier run */
    snprintf(path, sizeof path, "%s/fluid.vtu", dir);
    return vtu_write(path, &f->cloud, sv->rt.binary);
}

static double propose_dt(struct solver *sv)
{
    struct fluid *f = (struct fluid *)sv;
    return sv->rt.adjust ? mps_propose_dt(&f->s, sv->rt.max_co)
                         : sv->rt.delta_t;
}

static int advance(struct solver *sv)
{
    struct fluid *f = (struct fluid *)sv;
    return mps_step(&f->s, sv->rt.dt);
}

/* A restart from the state written builds its neighbour list (and
 * numbering) afresh: so does the continuing run, so that the two agree to
 * round-off. */
static int prepare_write(struct solver *sv)
{
    mps_request_rebuild(&((struct fluid *)sv)->s);
    return SIM_OK;
}

/* -relax: every particle at rest (the soil's last accelerations too).
 * Walls that move or are removed at a time would be moved by the
 * relaxation: refused. */
static int rest(struct solver *sv)
{
    struct fluid *f = (struct fluid *)sv;
    struct mps_particles *P = &f->s.P;
    if (f->s.walls_move)
        return sim_error(SIM_ERR_INPUT, "system/particleDict: -relax needs "
                         "walls that stay put, and a wall region has a "
                         "motion or removeAt (the relaxation would move "
                         "it): relax a copy of the case without them");
    memset(P->u, 0, sizeof *P->u * 3 * (size_t)P->n);
    if (P->accel)
        memset(P->accel, 0, sizeof *P->accel * 3 * (size_t)P->n);
    return SIM_OK;
}

static void progress(struct solver *sv, char *buf, size_t n)
{
    const struct mps_solver *s = &((struct fluid *)sv)->s;
    const struct store *w = ((struct fluid *)sv)->whole;
    snprintf(buf, n, "PPE: %d iterations, residual %.3g  particles %d  "
             "escaped %ld", s->last.iters, s->last.res_rel,
             w ? (int)w->n : s->P.n, s->n_escaped);
}

static void final_stats(struct solver *sv)
{
    const struct fluid *f = (const struct fluid *)sv;
    const struct mps_timers *t = &f->s.t;
    double ps = (double)f->s.P.n * (double)(t->steps ? t->steps : 1);
    double wall = app_wall_time() - f->sv.app.wall0;
    double sum = t->neighbours + t->explicit_ + t->assembly + t->ppe
               + t->correction;
    log_info("\nMPS statistics");
    log_info("    steps                 %ld (neighbour lists built %ld)",
             t->steps, t->builds);
    log_info("    particles             %d (escaped %ld)", f->s.P.n,
             f->s.n_escaped);
    app_log_peak_memory(f->s.P.n);
    log_info("    PPE iterations        %ld (%.1f per step)", t->ppe_iters,
             t->steps ? (double)t->ppe_iters / t->steps : 0.0);
    log_info("    time per particle-step [us]: neighbours %.3f  explicit "
             "%.3f  assembly %.3f  PPE %.3f  correction %.3f  total %.3f",
             1e6 * t->neighbours / ps, 1e6 * t->explicit_ / ps,
             1e6 * t->assembly / ps, 1e6 * t->ppe / ps,
             1e6 * t->correction / ps, 1e6 * sum / ps);
    if (t->ppe_row_iters > 0)
        log_info("    PPE per iteration     %.3f ns per row, %.1f nonzeros "
                 "per row (iterations only; preconditioner set-up %.3g s, "
                 "iterations %.3g s of PPE %.3g s)",
                 1e9 * t->ppe_solve / t->ppe_row_iters,
                 t->ppe_nnz_iters / t->ppe_row_iters, t->ppe_setup,
                 t->ppe_solve, t->ppe);
    log_info("    particle-steps/s      %.4g (wall clock of the run %.3g s)",
             wall > 0 ? ps / wall : 0.0, wall);
#ifdef MPSDEM_HAVE_MPI
    if (f->dist) {
        struct dist_stats d;
        dist_stats(f->dist, &d);
        log_info("    distributed           %d ranks (the numbers above: "
                 "rank 0's), own particles %ld-%ld per rank now, %ld "
                 "migrations in %ld exchanges, regions cut afresh %ld "
                 "times, ghosts per rank %.0f (mean), %.0f (largest rank)",
                 d.ranks, d.own_min, d.own_max, d.migrated, d.exchanges,
                 d.balances, d.ghosts_mean, d.ghosts_max);
    }
#endif
}

static void cleanup(struct solver *sv)
{
    struct fluid *f = (struct fluid *)sv;
    couple_fluid_free(&f->cf);
#ifdef MPSDEM_HAVE_MPI
    dist_free(f->dist);
#endif
    mps_solver_free(&f->s);
    dict_free(f->transport);
    dict_free(f->gravity);
    dict_free(f->schemes);
    dict_free(f->solution);
    dict_free(f->patches);
    dict_free(f->particles);
    dict_free(f->soil_dict);
    for (int k = 0; k < MAX_PATCHES; k++)
        wall_motion_free(&f->motion[k]);
}

static void list_models(void)
{
    model_choices_print(mps_choices, NULL, NULL);
    model_choices_print(linsolve_choices, "system/mpsSolution", "PPE/");
    model_choices_print(coupling_choices, NULL, NULL);
}

/* Coupled (doc/design.md §4): before each step the fluid state at the
 * grains goes to demSolid and the grains' state at the end of the step
 * comes back; the step then sees them through inv_eps and f_ext. */
static int couple_open(struct solver *sv)
{
    struct fluid *f = (struct fluid *)sv;
    return couple_fluid_open(&f->cf, &f->s, sv->coupling, sv->app.case_abs,
                             "mpsFluid", sv->rt.end_time);
}

static int couple_before(struct solver *sv)
{
    struct fluid *f = (struct fluid *)sv;
    TRY(couple_fluid_exchange(&f->cf, &f->s, sv->rt.step, sv->rt.value,
                              sv->rt.dt));
    couple_fluid_reaction_field(&f->cf, &f->s.P, f->reaction);
    return SIM_OK;
}

static void couple_finish(struct solver *sv)
{
    const struct fluid *f = (const struct fluid *)sv;
    log_info("Coupling: %ld exchanges, %ld pair searches, %.3g s in the "
             "glue, %.3g s waiting for demSolid", f->cf.exchanges,
             f->cf.searches, f->cf.wall, f->cf.wait);
}

static void couple_close(struct solver *sv, int rc)
{
    couple_fluid_close(&((struct fluid *)sv)->cf, rc);
}

static const struct solver_coupling coupling = {
    .open = couple_open,
    .before_step = couple_before,
    .finish = couple_finish,
    .close = couple_close,
};

static const struct fo_ops *const *const fo_tables[] = {
    fo_generic_table, mps_fo_table, NULL };

static const struct solver_ops fluid_ops = {
    .name = "mpsFluid",
    .description = "incompressible MPS solver for free-surface flows",
    .cloud = "fluid",
    .peer_cloud = "dem",
    .list_models = list_models,
    .create = create,
    .fo_tables = fo_tables,
    .refresh_scene = refresh_scene,
    .propose_dt = propose_dt,
    .advance = advance,
    .dump_failed_advance = 1,
    .prepare_write = prepare_write,
    .write = write_fields,
    .progress = progress,
    .stats = final_stats,
    .rest = rest,
    .cleanup = cleanup,
    .coupling = &coupling,
    .parallel = 1,
};

int main(int argc, char **argv)
{
    static struct fluid f;
    return solver_main(&fluid_ops, &f.sv, argc, argv);
}
