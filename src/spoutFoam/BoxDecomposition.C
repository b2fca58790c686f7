/*---------------------------------------------------------------------------*\
    SpoutLab: the boxes of a parallel run.
\*---------------------------------------------------------------------------*/
#include "BoxDecomposition.H"

#include "InputError.hpp"
#include "ShortNumbers.H"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace spoutlab
{

namespace
{

const char* const axisName[3] = {"x", "y", "z"};


void sumOverRanks(std::vector<double>& values)
{
    MPI_Allreduce
    (
        MPI_IN_PLACE, values.data(), int(values.size()), MPI_DOUBLE, MPI_SUM,
        MPI_COMM_WORLD
    );
}


// Every rank's bounds of its cells, 3 per rank (not reduced)
void rankBounds
(
    const Foam::fvMesh& mesh, std::vector<double>& lo, std::vector<double>& hi
)
{
    const std::size_t me = std::size_t(Foam::Pstream::myProcNo());
    lo.assign(3*std::size_t(Foam::Pstream::nProcs()), 0.0);
    hi = lo;
    const Foam::boundBox local(mesh.points(), false);
    for (int a = 0; a < 3; ++a)
    {
        lo[3*me + a] = local.min()[a];
        hi[3*me + a] = local.max()[a];
    }
    sumOverRanks(lo);
    sumOverRanks(hi);
}


std::string rankSpan(const std::vector<double>& lo, const std::vector<double>& hi, std::size_t r)
{
    std::string span;
    for (int a = 0; a < 3; ++a)
    {
        span += std::string(a ? ", " : "") + axisName[a] + " " + format(lo[3*r + a])
          + " to " + format(hi[3*r + a]);
    }
    return span + " m";
}


[[noreturn]] void notAGrid
(
    const std::vector<double>& lo, const std::vector<double>& hi,
    std::size_t r, const std::string& why
)
{
    throw InputError
    (
        "system/decomposeParDict: the coupling expects the ranks' cells in a "
        "grid of boxes, one per rank (method simple, hierarchical with the "
        "same cuts in every column, or etc/caseFunctions decomposeSlabs); "
        "rank " + std::to_string(r) + " spans " + rankSpan(lo, hi, r) + ": " + why
    );
}


// The planes along axis a where one rank's cells end and another's begin
std::vector<double> planesAlong
(
    const std::vector<double>& lo, const std::vector<double>& hi, int a, double tol
)
{
    const std::size_t nProcs = lo.size()/3;
    std::vector<double> planes;
    for (std::size_t s = 0; s < nProcs; ++s)
    {
        const double x = lo[3*s + a];
        bool shared = false;
        for (std::size_t r = 0; r < nProcs; ++r)
        {
            shared = shared || std::abs(hi[3*r + a] - x) <= tol;
        }
        bool known = false;
        for (const double p : planes) known = known || std::abs(p - x) <= tol;
        if (shared && !known) planes.push_back(x);
    }
    std::sort(planes.begin(), planes.end());
    return planes;
}


// The grid of boxes the ranks' cells form, each rank's place in it
ProcessorGrid meshGrid(const Foam::fvMesh& mesh)
{
    std::vector<double> lo, hi;
    rankBounds(mesh, lo, hi);
    const std::size_t nProcs = lo.size()/3;
    double size = 0;
    for (std::size_t k = 0; k < lo.size(); ++k) size = std::max(size, std::abs(hi[k] - lo[k]));
    const double tol = 1e-9*size;

    ProcessorGrid grid;
    grid.box.assign(nProcs, {{0, 0, 0}});
    for (int a = 0; a < 3; ++a)
    {
        const std::vector<double> planes = planesAlong(lo, hi, a, tol);
        grid.cuts[a] = planes;
        grid.n[a] = int(planes.size()) + 1;
        for (std::size_t r = 0; r < nProcs; ++r)
        {
            int i = 0;
            while (i < int(planes.size()) && planes[i] <= lo[3*r + a] + tol) ++i;
            if (i < int(planes.size()) && hi[3*r + a] > planes[i] + tol)
            {
                notAGrid(lo, hi, r, std::string("it crosses the cut ") + axisName[a]
                  + " = " + format(planes[i]) + " m of other ranks");
            }
            grid.box[r][a] = i;
        }
    }
    if (std::size_t(grid.n[0]*grid.n[1]*grid.n[2]) != nProcs)
    {
        notAGrid
        (
            lo, hi, 0, "the cuts make " + std::to_string(grid.n[0]) + " x "
          + std::to_string(grid.n[1]) + " x " + std::to_string(grid.n[2])
          + " boxes for " + std::to_string(nProcs) + " ranks"
        );
    }
    for (std::size_t r = 0; r < nProcs; ++r)
    {
        if (grid.rankAt(grid.box[r]) != int(r))
        {
            notAGrid(lo, hi, r, "rank " + std::to_string(grid.rankAt(grid.box[r]))
              + " holds the same box");
        }
    }
    return grid;
}


// A box narrower than the particles' reach along a cut axis would put a
// particle's pieces beyond the neighbour's halo.
void checkWidths(const Foam::fvMesh& mesh, const ProcessorGrid& grid, double reach)
{
    std::vector<double> lo, hi;
    rankBounds(mesh, lo, hi);
    for (std::size_t r = 0; r < grid.box.size(); ++r)
    {
        for (int a = 0; a < 3; ++a)
        {
            const double width = hi[3*r + a] - lo[3*r + a];
            if (grid.n[a] == 1 || width >= reach) continue;
            throw InputError
            (
                "system/decomposeParDict: the box of rank " + std::to_string(r)
              + " is " + format(width) + " m wide in " + axisName[a] + ", less "
                "than the particles' reach (largest radius + LIGGGHTS skin, "
              + format(reach) + " m); run on fewer ranks"
            );
        }
    }
}


void reportGrid(const ProcessorGrid& grid, const FoamCellLocator& locator, double reach)
{
    std::vector<double> halo(Foam::Pstream::nProcs(), 0.0);
    halo[Foam::Pstream::myProcNo()] = double(locator.nHaloCells());
    sumOverRanks(halo);
    Foam::Info<< "Parallel coupling: ";
    if (grid.n[1] == 1 && grid.n[2] == 1)
    {
        Foam::Info<< grid.n[0] << " x-slabs cut at";
        for (const double x : grid.cuts[0]) Foam::Info<< ' ' << x;
    }
    else
    {
        Foam::Info<< grid.n[0] << " x " << grid.n[1] << " x " << grid.n[2]
            << " boxes cut at";
        for (int a = 0; a < 3; ++a)
        {
            if (grid.cuts[a].empty()) continue;
            Foam::Info<< ' ' << axisName[a];
            for (const double x : grid.cuts[a]) Foam::Info<< ' ' << x;
        }
    }
    Foam::Info<< " m; halo cells per rank (reach " << reach << " m):";
    for (const double h : halo) Foam::Info<< ' ' << Foam::label(h);
    Foam::Info<< Foam::endl;
}

} // namespace


void matchDecomposition
(
    const Foam::fvMesh& mesh, LiggghtsDem& dem, FoamCellLocator& locator
)
{
    // each rank's atoms in its own cells; what they reach of the
    // neighbours' cells becomes its halo
    const ProcessorGrid grid = meshGrid(mesh);
    const double reach = dem.reach();
    checkWidths(mesh, grid, reach);
    dem.setDecomposition(grid);
    locator.addHalo(grid, reach);
    reportGrid(grid, locator, reach);
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
