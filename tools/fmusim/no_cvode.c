/* trackgen: fmusim built without SUNDIALS CVODE. Co-simulation needs no
 * solver in the importer; model exchange with --solver cvode reports that
 * this build lacks it. (Replaces fmusim/FMICVode.c, which needs CVODE.) */
#include <stdio.h>
#include "FMICVode.h"

FMISolver* FMICVodeCreate(const FMISolverParameters* solverFunctions) {
    (void)solverFunctions;
    fprintf(stderr, "fmusim: this build has no CVODE (use --solver euler, or co-simulation)\n");
    return NULL;
}

void FMICVodeFree(FMISolver* solver) { (void)solver; }

FMISolverStatus FMICVodeStep(FMISolver* solver, double nextTime, double* timeReached, bool* stateEvent) {
    (void)solver; (void)nextTime; (void)timeReached; (void)stateEvent;
    return FMISolverError;
}

FMISolverStatus FMICVodeReset(FMISolver* solver, double time) {
    (void)solver; (void)time;
    return FMISolverError;
}
