/*---------------------------------------------------------------------------*\
    SpoutLab: the x-slabs of a parallel run.
\*---------------------------------------------------------------------------*/
#include "SlabDecomposition.H"

#include "InputError.hpp"
#include "ShortNumbers.H"

#include <mpi.h>

#include <cmath>
#include <vector>

namespace spoutlab
{

namespace
{

void sumOverRanks(std::vector<double>& values)
{
    MPI_Allreduce
    (
        MPI_IN_PLACE, values.data(), int(values.size()), MPI_DOUBLE, MPI_SUM,
        MPI_COMM_WORLD
    );
}


// The x-planes between the ranks' cells (P + 1, in rank order).
std::vector<double> meshSlabs(const Foam::fvMesh& mesh)
{
    const Foam::label nProcs = Foam::Pstream::nProcs();
    std::vector<double> lo(nProcs, 0), hi(nProcs, 0);
    const Foam::boundBox local(mesh.points(), false);   // not reduced
    lo[Foam::Pstream::myProcNo()] = local.min().x();
    hi[Foam::Pstream::myProcNo()] = local.max().x();
    sumOverRanks(lo);
    sumOverRanks(hi);
    const double tol = 1e-9*(hi.back() - lo.front());
    for (Foam::label r = 1; r < nProcs; ++r)
    {
        if (std::abs(lo[r] - hi[r-1]) > tol)
        {
            throw InputError
            (
                "system/decomposeParDict: the coupling expects the mesh in "
                "x-slabs in rank order (etc/caseFunctions decomposeSlabs); "
                "rank " + std::to_string(r - 1) + " spans x " + format(lo[r-1])
              + " to " + format(hi[r-1]) + " m, rank " + std::to_string(r)
              + " " + format(lo[r]) + " to " + format(hi[r]) + " m"
            );
        }
    }
    std::vector<double> cuts(lo);
    cuts.push_back(hi.back());
    return cuts;
}


// A slab narrower than the particles' reach would put a particle's pieces
// beyond the neighbour's halo.
void checkWidths(const std::vector<double>& cuts, double reach)
{
    for (std::size_t r = 0; r + 1 < cuts.size(); ++r)
    {
        if (cuts[r + 1] - cuts[r] < reach)
        {
            throw InputError
            (
                "system/decomposeParDict: the x-slab of rank " + std::to_string(r)
              + " is " + format(cuts[r + 1] - cuts[r]) + " m wide, less than "
                "the particles' reach (largest radius + LIGGGHTS skin, "
              + format(reach) + " m); run on fewer ranks"
            );
        }
    }
}

} // namespace


void matchSlabs(const Foam::fvMesh& mesh, LiggghtsDem& dem, FoamCellLocator& locator)
{
    // each rank's atoms in its own cells; what they reach of the
    // neighbours' cells becomes its halo
    const std::vector<double> cuts = meshSlabs(mesh);
    const double reach = dem.reach();
    checkWidths(cuts, reach);
    dem.setSlabs(cuts);
    locator.addHalo(cuts, reach);

    std::vector<double> halo(Foam::Pstream::nProcs(), 0.0);
    halo[Foam::Pstream::myProcNo()] = double(locator.nHaloCells());
    sumOverRanks(halo);
    Foam::Info<< "Parallel coupling: " << Foam::Pstream::nProcs()
        << " x-slabs cut at";
    for (std::size_t r = 1; r + 1 < cuts.size(); ++r) Foam::Info<< ' ' << cuts[r];
    Foam::Info<< " m; halo cells per rank (reach " << reach << " m):";
    for (const double h : halo) Foam::Info<< ' ' << Foam::label(h);
    Foam::Info<< Foam::endl;
}



void reportHaloTraffic(const FoamCellLocator& locator, double steps)
{
    const Foam::label nProcs = Foam::Pstream::nProcs();
    std::vector<double> messages(nProcs, 0.0), bytes(nProcs, 0.0);
    messages[Foam::Pstream::myProcNo()] = locator.traffic().messages/steps;
    bytes[Foam::Pstream::myProcNo()] = locator.traffic().bytes/steps;
    sumOverRanks(messages);
    sumOverRanks(bytes);
    Foam::Info<< "Halo exchange per step, by rank (messages, kB):";
    for (Foam::label r = 0; r < nProcs; ++r)
    {
        Foam::Info<< " (" << messages[r] << ", " << bytes[r]/1024 << ")";
    }
    Foam::Info<< Foam::endl;
}

} // namespace spoutlab
