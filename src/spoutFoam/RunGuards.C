/*---------------------------------------------------------------------------*\
    SpoutLab: the guards that stop a coupled run with one line.
\*---------------------------------------------------------------------------*/
#include "RunGuards.H"

#include "OStringStream.H"

#include "DemTimeStep.hpp"
#include "InputError.hpp"
#include "RankGather.H"
#include "ShortNumbers.H"

#include <mpi.h>

#include <algorithm>
#include <cmath>

namespace spoutlab
{

namespace
{

bool finite(double x) { return std::isfinite(x); }
bool finite(const Foam::vector& v)
{
    return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z());
}
bool finite(const Vec3& v)
{
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

template<class Type>
std::string text(const Type& value)
{
    Foam::OStringStream os;
    os << value;
    return os.str();
}

std::string where(const Foam::vector& c)
{
    std::string at = format(Vec3{c.x(), c.y(), c.z()});
    if (Foam::Pstream::parRun())
    {
        at += " of processor " + std::to_string(Foam::Pstream::myProcNo());
    }
    return at;
}

} // namespace


std::string foundOnAnyRank(const std::string& found)
{
    int rank = 0, nProcs = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &nProcs);
    int first = found.empty() ? nProcs : rank;
    MPI_Allreduce(MPI_IN_PLACE, &first, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
    if (first == nProcs) return std::string();

    int n = int(found.size());
    MPI_Bcast(&n, 1, MPI_INT, first, MPI_COMM_WORLD);
    std::string what(found);
    what.resize(std::size_t(n));
    MPI_Bcast(&what[0], n, MPI_CHAR, first, MPI_COMM_WORLD);
    return what;
}


template<class Type>
void checkStartField
(
    const Foam::GeometricField<Type, Foam::fvPatchField, Foam::volMesh>& field
)
{
    const Foam::fvMesh& mesh = field.mesh();
    std::string found;
    const Foam::Field<Type>& cells = field.primitiveField();
    forAll(cells, celli)
    {
        if (finite(cells[celli])) continue;
        found = "got " + text(cells[celli]) + " in cell " + std::to_string(celli)
              + " " + where(mesh.C()[celli]);
        break;
    }
    forAll(field.boundaryField(), patchi)
    {
        const Foam::fvPatchField<Type>& values = field.boundaryField()[patchi];
        if (!found.empty()) break;
        if (values.coupled()) continue;   // the neighbour's cells, checked there
        forAll(values, facei)
        {
            if (finite(values[facei])) continue;
            found = "got " + text(values[facei]) + " on patch "
                  + values.patch().name() + ", face " + std::to_string(facei) + " "
                  + where(mesh.Cf().boundaryField()[patchi][facei]);
            break;
        }
    }
    found = foundOnAnyRank(found);
    if (found.empty()) return;
    throw InputError
    (
        std::string(mesh.time().timeName()) + "/" + field.name()
      + ": expected finite values, " + found
    );
}

template void checkStartField(const Foam::volScalarField&);
template void checkStartField(const Foam::volVectorField&);


RunGuards::RunGuards(const Foam::fvMesh& mesh)
:
    mesh_(mesh),
    lastWritten_(mesh.time().timeName())
{}


void RunGuards::stopIfAnyRank(const std::string& found) const
{
    const std::string what = foundOnAnyRank(found);
    if (what.empty()) return;
    throw InputError
    (
        what + " at t = " + mesh_.time().timeName() + " s; nothing of this "
        "step was written, the last good state is time " + lastWritten_
      + " (startFrom latestTime restarts from it)"
    );
}


template<class Type>
void RunGuards::checkField
(
    const Foam::GeometricField<Type, Foam::fvPatchField, Foam::volMesh>& field
) const
{
    std::string found;
    // a boundary that imposes its value (an inlet) first: the likely origin
    forAll(field.boundaryField(), patchi)
    {
        const Foam::fvPatchField<Type>& values = field.boundaryField()[patchi];
        if (values.coupled() || values.assignable() || !found.empty()) continue;
        forAll(values, facei)
        {
            if (finite(values[facei])) continue;
            found = "non-finite " + field.name() + " on patch " + values.patch().name()
                  + ", face " + std::to_string(facei) + " "
                  + where(mesh_.Cf().boundaryField()[patchi][facei]);
            break;
        }
    }
    const Foam::Field<Type>& values = field.primitiveField();
    forAll(values, celli)
    {
        if (!found.empty()) break;
        if (finite(values[celli])) continue;
        found = "non-finite " + field.name() + " in cell " + std::to_string(celli)
              + " " + where(mesh_.C()[celli]);
    }
    stopIfAnyRank(found);
}

template void RunGuards::checkField(const Foam::volScalarField&) const;
template void RunGuards::checkField(const Foam::volVectorField&) const;


void RunGuards::checkParticles(const std::vector<Particle>& particles) const
{
    std::string found;
    for (const Particle& p : particles)
    {
        if (finite(p.x) && finite(p.v) && finite(p.radius) && finite(p.temperature))
        {
            continue;
        }
        found = "non-finite position, velocity, radius or temperature of particle "
              + std::to_string(p.id) + " (x " + format(p.x) + ", v " + format(p.v)
              + ", r " + format(p.radius) + " m, T " + format(p.temperature) + " K)";
        break;
    }
    stopIfAnyRank(found);
}


template<class Value>
void RunGuards::checkParticles
(
    const std::string& what,
    const std::vector<Value>& values,
    const std::vector<Particle>& particles
) const
{
    std::string found;
    for (std::size_t i = 0; i < values.size(); ++i)
    {
        if (finite(values[i])) continue;
        found = "non-finite " + what + " on particle "
              + std::to_string(particles[i].id) + " " + format(particles[i].x);
        break;
    }
    stopIfAnyRank(found);
}

template void RunGuards::checkParticles
(
    const std::string&, const std::vector<double>&, const std::vector<Particle>&
) const;
template void RunGuards::checkParticles
(
    const std::string&, const std::vector<Vec3>&, const std::vector<Particle>&
) const;


std::vector<long> RunGuards::lostParticles
(
    const std::vector<std::size_t>& lost,
    const std::vector<Particle>& particles,
    bool deleteLost
) const
{
    // A rank's atoms lie in its cells or its halo; a centre in neither is
    // outside the mesh.
    std::vector<long> ids;
    for (const std::size_t i : lost) ids.push_back(particles[i].id);
    ids = gathered(ids, MPI_COMM_WORLD, true);
    if (ids.empty()) return ids;

    std::sort(ids.begin(), ids.end());   // the same line on any ranks
    std::string list;
    for (std::size_t k = 0; k < ids.size() && k < 20; ++k)
    {
        list += (k ? ", " : "") + std::to_string(ids[k]);
    }
    if (ids.size() > 20) list += ", ...";
    const std::string what =
        std::to_string(ids.size()) + " particle(s) outside the CFD mesh at t = "
      + mesh_.time().timeName() + " s (ids " + list + ")";
    if (!deleteLost)
    {
        throw InputError
        (
            what + "; set 'lostParticles delete' in "
            "constant/couplingProperties to remove them instead"
        );
    }
    Foam::Info<< "spoutFoam: deleting " << what.c_str() << Foam::endl;
    return ids;
}


void RunGuards::checkTimeSteps
(
    const LiggghtsDem& dem,
    Foam::label couplingInterval,
    const std::string& liggghtsInput
) const
{
    const double dtDem = dem.timeStep();
    const double dtCfd = mesh_.time().deltaTValue();
    if (std::abs(dtCfd - couplingInterval*dtDem) > 1e-9*dtCfd)
    {
        throw InputError
        (
            "system/controlDict: key 'deltaT' expected couplingInterval ("
          + std::to_string(couplingInterval) + ") x LIGGGHTS time step ("
          + format(dtDem) + " s) = " + format(couplingInterval*dtDem)
          + " s, got " + format(dtCfd) + " s"
        );
    }

    const double k = dem.maxNormalStiffness();
    const double m = dem.minParticleMass();
    if (k <= 0 || dem.nParticles() == 0) return;
    const double limit = demTimeStepLimit(m, k);
    if (dtDem > limit*(1 + 1e-9))   // round-off: dt exactly at the limit is fine
    {
        throw InputError
        (
            "LIGGGHTS input '" + liggghtsInput + "': DEM time step "
          + format(dtDem)
          + " s exceeds the limit of eq 11, pi*sqrt(m/k)/5 = "
          + format(limit) + " s (lightest particle m = " + format(m)
          + " kg, largest k_n = " + format(k) + " N/m)"
        );
    }
}


void RunGuards::checkCourant
(
    const Foam::surfaceScalarField& phiU,
    Foam::scalar maxCo
) const
{
    const Foam::scalarField sumPhi
    (
        Foam::fvc::surfaceSum(Foam::mag(phiU))().primitiveField()
    );
    const Foam::scalar Co =
        0.5*Foam::gMax(sumPhi/mesh_.V().field())*mesh_.time().deltaTValue();
    Foam::Info<< "Courant number (interstitial) max: " << Co << Foam::endl;
    if (!(Co <= maxCo))   // a NaN too
    {
        throw InputError
        (
            "gas Courant number " + format(Co) + " at t = "
          + mesh_.time().timeName() + " s exceeds maxCo " + format(maxCo)
          + " (constant/couplingProperties); reduce deltaT and couplingInterval"
        );
    }
}

} // namespace spoutlab
