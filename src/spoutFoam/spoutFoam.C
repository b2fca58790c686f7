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
#include "reverseLinear.H"

#include "DemCoupling.H"
#include "FluxVelocity.H"
#include "InputError.hpp"
#include "ModelFamilies.hpp"

#include <mpi.h>

#include <cfenv>
#include <cstdlib>
#include <string>


//- Bad input: one line on the master; one write, so that another rank's
//  MPI_Abort banner cannot split it
static int stopOnInput(const spoutlab::InputError& err)
{
    if (Pstream::master())
    {
        std::cerr << (std::string("spoutFoam: ") + err.what() + "\n") << std::flush;
    }
    return 1;
}


//- A model outside its domain (e.g. a psychrometric function given a
//  negative humidity): one line, from the rank that found it
static int stopInModel(const Time& runTime, const std::exception& err)
{
    std::cerr << ("spoutFoam: stopped at t = " + runTime.timeName() + " s: " + err.what() + "\n")
        << std::flush;
    return 1;
}


int main(int argc, char *argv[])
{
    #include "spoutFoamOptions.H"
    #include "postProcess.H"
    #include "setRootCaseLists.H"
    #include "listModels.H"
    #include "createTime.H"
    #include "createMesh.H"
    #include "floatingPointTraps.H"
    #include "startMpi.H"

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

            coupling.evolve();        // DEM steps; eps, Us, Ksl, particle forces

            // PISO: one momentum predictor, then the pressure correctors;
            // a NaN stops the step before it reaches the next solver
            #include "UEqn.H"
            coupling.checkGas();
            while (piso.correct())
            {
                #include "pEqn.H"
                coupling.checkGas();
            }

            coupling.solveEnergy();   // gas energy and particle heat, if any
            coupling.endStep(phiU);   // Courant guard, the row of coupling.csv

            #include "writeTimes.H"
            coupling.write();
            runTime.printExecutionTime(Info);
        }
        coupling.finish();
        Info<< "End\n" << endl;
    }
    catch (const spoutlab::InputError& err)
    {
        status = stopOnInput(err);
    }
    catch (const std::exception& err)
    {
        status = stopInModel(runTime, err);
    }

    #include "finishRun.H"
}
