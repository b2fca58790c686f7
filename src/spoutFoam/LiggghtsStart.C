/*---------------------------------------------------------------------------*\
    SpoutLab: the case's LIGGGHTS instance.
\*---------------------------------------------------------------------------*/
#include "LiggghtsStart.H"

#include "CoarseGraining.hpp"
#include "FoamParameters.H"
#include "InputError.hpp"
#include "LiggghtsInputCheck.H"

#include <cstdio>
#include <map>

namespace spoutlab
{

namespace
{

std::map<std::string, std::string> liggghtsVariables
(
    const Foam::Time& runTime,
    const Foam::dictionary& couplingDict,
    double coarseGraining
)
{
    const Foam::fileName demDir = runTime.globalPath()/"DEM";
    std::map<std::string, std::string> vars;
    vars["case"] = runTime.globalPath();
    vars["dem"] = demDir;
    if (const Foam::dictionary* user = couplingDict.findDict("liggghtsVariables"))
    {
        checkNoOwnCg(user->found("cg"), "constant/couplingProperties");
        Parameters params = toParameters(couplingDict, "liggghtsVariables");
        for (const Foam::word& key : user->toc()) vars[key] = params.getWord(key);
    }
    // the coarse-graining factor, for the input to scale its parcels by
    char cg[32];
    std::snprintf(cg, sizeof cg, "%.17g", coarseGraining);
    vars["cg"] = cg;
    if (runTime.value() > 0)
    {
        const Foam::fileName restart =
            demDir/("restart_" + runTime.timeName() + ".liggghts");
        if (!Foam::isFile(restart))
        {
            throw InputError
            (
                "restart at t = " + runTime.timeName()
              + " s needs the LIGGGHTS restart '" + restart + "' (missing)"
            );
        }
        vars["restart"] = restart;
    }
    return vars;
}

} // namespace


std::unique_ptr<LiggghtsDem> startLiggghts
(
    const Foam::Time& runTime,
    const Foam::dictionary& couplingDict,
    std::string& inputFile,
    int moistureState,
    int circulationTrack
)
{
    const Foam::fileName caseDir = runTime.globalPath();
    if (Foam::Pstream::master()) Foam::mkDir(caseDir/"DEM");
    const double cg = coarseGrainingEntry(couplingDict, "constant/couplingProperties");
    std::map<std::string, std::string> vars = liggghtsVariables(runTime, couplingDict, cg);

    Foam::fileName input = couplingDict.get<Foam::fileName>("liggghtsInput");
    input.expand();
    if (!input.isAbsolute()) input = caseDir/input;
    vars["inputDir"] = input.path();   // for includes beside the input
    inputFile = input;
    if (Foam::isFile(input))   // else LiggghtsDem names the missing input
    {
        checkCoarseGrainedInput
        (
            cg, usesVariable(input, vars, "cg"), "constant/couplingProperties", input
        );
    }
    std::unique_ptr<LiggghtsDem> dem
    (
        new LiggghtsDem
        (
            input, vars, caseDir/"log.liggghts", MPI_COMM_WORLD, moistureState,
            circulationTrack
        )
    );
    dem->setCoarseGraining(cg);
    return dem;
}

} // namespace spoutlab
