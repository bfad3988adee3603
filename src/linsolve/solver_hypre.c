/*
 * solver_hypre.c — placeholder entry for hypre BoomerAMG-PCG
 * (toolchain.md §2 point 3). Not built: the Debian hypre needs mpicc and
 * MPI_Init, which the default build does not have. The entry exists so that
 * `solver hypre;` gets a clear message instead of "unknown solver".
 */
#include "core/error.h"
#include "linsolve/linsolve_impl.h"

static int init(struct linsolve *s)
{
    (void)s;
    return sim_error(SIM_ERR_INPUT, "solver 'hypre' is not available in this "
                     "build (hypre BoomerAMG support is not compiled in); use "
                     "pcg (with jacobi, ic0 or dic) or cholmod");
}

const struct solver_ops solver_hypre = {
    .name = "hypre",
    .reference = "hypre BoomerAMG-PCG (not compiled in)",
    .iterative = 1, .needs_symmetric = 0, .needs_spd_pc = 0,
    .init = init,
};
