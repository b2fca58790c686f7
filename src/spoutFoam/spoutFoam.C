/*---------------------------------------------------------------------------*\
Application
    spoutFoam

Description
    CFD-DEM solver for dense gas-particle flows (spouted and fluidised beds).
    The gas is the volume-averaged incompressible phase of Tsuji's "model A"
    solved with PISO; the particles are an in-process LIGGGHTS instance.
    Each time step: LIGGGHTS advances couplingInterval steps with the fluid
    force of the last exchange; particles are located, the void fraction,
    the cell-averaged particle velocity Us and the exchange coefficient Ksl
    (beta) are computed; the fluid forces go back to LIGGGHTS; then the gas
    is solved with beta*(Us - U) implicit in U.  With heat transfer, the gas
    energy equation follows, with the exchange implicit in T, and each
    particle's heat flux goes back to LIGGGHTS.  Settings are in
    constant/couplingProperties.
\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "pisoControl.H"
#include "fixedFluxPressureFvPatchScalarField.H"
#include "uniformDimensionedFields.H"

#include "DemCoupling.H"
#include "InputError.hpp"
#include "ModelFamilies.hpp"

#include <mpi.h>

#include <cfenv>
#include <cstdlib>

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "CFD-DEM solver: volume-averaged gas (model A, PISO) coupled to an"
        " in-process LIGGGHTS; see constant/couplingProperties"
    );

    // the names each run-time selection accepts, from the models' registries
    argList::addBoolOption
    (
        "listModels",
        "List the names dragModel, voidFractionModel and heatTransferModel"
        " accept, one family a line, and exit"
    );
    argList::addNote("");
    for (const spoutlab::ModelFamily& family : spoutlab::modelFamilies())
    {
        argList::addNote(family.key + ": " + family.names);
    }

    #include "postProcess.H"

    #include "setRootCaseLists.H"
    if (args.found("listModels"))
    {
        for (const spoutlab::ModelFamily& family : spoutlab::modelFamilies())
        {
            Info<< family.key.c_str() << ": " << family.names.c_str() << nl;
        }
        return 0;
    }
    #include "createTime.H"
    #include "createMesh.H"

    // OpenFOAM's trapFpe turns the first overflow or invalid operation into
    // a SIGFPE and a stack trace.  spoutFoam lets the NaN or Inf through to
    // its guards instead, which stop the step with one line naming the
    // field, the cell (or particle) and the time.  FOAM_SIGFPE set in the
    // environment keeps OpenFOAM's choice, e.g. to find the operation.
    if (!std::getenv("FOAM_SIGFPE"))
    {
        fedisableexcept(FE_DIVBYZERO | FE_INVALID | FE_OVERFLOW);
    }

    // LIGGGHTS needs MPI even when the case runs serial (OpenFOAM only
    // starts MPI with -parallel).
    int mpiStarted = 0;
    MPI_Initialized(&mpiStarted);
    const bool ownMpi = !mpiStarted;
    if (ownMpi) MPI_Init(&argc, &argv);

    int status = 0;
    try
    {
        pisoControl piso(mesh);

        #include "createFields.H"

        spoutlab::DemCoupling coupling(mesh, U, p, voidfraction, phi, rho, mu, g);

        Info<< "\nStarting time loop\n" << endl;

        while (runTime.loop())
        {
            Info<< "Time = " << runTime.timeName() << nl << endl;

            coupling.evolve();

            // PISO: one momentum predictor, then the pressure correctors
            #include "UEqn.H"
            coupling.checkGas();   // before a NaN reaches the pressure solver
            while (piso.correct())
            {
                #include "pEqn.H"
                coupling.checkGas();
            }

            coupling.logGasMomentum();

            // gas energy (eq 4) and the particles' heat, if the case has them
            coupling.solveEnergy();

            coupling.checkCourant(phiU);
            // the last step is always written: the final state, the time
            // averages up to the end, and a restart point
            const bool last =
                runTime.value() > runTime.endTime().value() - 0.5*runTime.deltaTValue();
            if (last && !runTime.writeTime())
            {
                runTime.writeNow();
            }
            else
            {
                runTime.write();
            }
            coupling.write();

            runTime.printExecutionTime(Info);
        }
        coupling.finish();
        Info<< "End\n" << endl;
    }
    catch (const spoutlab::InputError& err)
    {
        if (Pstream::master())
        {
            std::cerr << "spoutFoam: " << err.what() << std::endl;
        }
        status = 1;
    }

    // argList's destructor ends the process with status 0, so a failure
    // must leave here
    if (status != 0 && Pstream::parRun())
    {
        Foam::UPstream::exit(status);
    }
    if (ownMpi)
    {
        MPI_Finalize();
    }
    if (status != 0)
    {
        std::exit(status);
    }
    return 0;
}
