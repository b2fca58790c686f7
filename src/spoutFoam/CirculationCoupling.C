/*---------------------------------------------------------------------------*\
    SpoutLab: circulation statistics measured in the coupled run.
\*---------------------------------------------------------------------------*/
#include "CirculationCoupling.H"

#include "IFstream.H"
#include "InputError.hpp"
#include "ShortNumbers.H"

#include <mpi.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numeric>
#include <sstream>

namespace spoutlab
{

namespace
{

const std::string file = "constant/couplingProperties";


double lengthEntry(const Foam::dictionary& dict, const std::string& where, const Foam::word& key)
{
    double value = 0;
    if (!dict.readIfPresent(key, value) || !std::isfinite(value))
    {
        throw InputError
        (
            where + ": key '" + key + "' expected a length in mm (circulation "
            "statistics, draft-plate geometry)"
        );
    }
    return 1e-3*value;
}


std::string number(double v)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.10g", std::isfinite(v) ? v : 0.0);
    return text;
}


// {"samples": n, "mean": s, "std": s}
std::string moments(const Moments& m)
{
    return "{\"samples\": " + number(m.samples) + ", \"mean\": " + number(m.mean())
        + ", \"std\": " + number(m.std()) + "}";
}


std::string countList(const std::vector<double>& counts)
{
    std::string list;
    for (std::size_t b = 0; b < counts.size(); ++b)
    {
        list += (b ? ", " : "") + number(counts[b]);
    }
    return "[" + list + "]";
}


// the completed residences, and those still open at the window's end by
// their time so far (censored)
std::string residenceEntry
(
    const ResidenceDistribution& d,
    double binWidth,
    const std::vector<double>& censored
)
{
    return "{\"binWidth\": " + number(binWidth) + ", \"counts\": " + countList(d.counts)
        + ", \"samples\": " + number(d.all.samples) + ", \"mean\": "
        + number(d.all.mean()) + ", \"std\": " + number(d.all.std())
        + ",\n      \"censored\": {\"counts\": " + countList(censored) + ", \"samples\": "
        + number(std::accumulate(censored.begin(), censored.end(), 0.0)) + "}}";
}


std::string distributionName(int index)
{
    return index == CirculationStatistics::cycle ? "cycle" : circulationRegionName(index);
}


double weighted(const ParticleCellMap::Row& row, const std::vector<double>& field)
{
    double sum = 0;
    for (const CellWeight& cw : row) sum += cw.weight*field[cw.cell];
    return sum;
}


double patchMean(const Foam::fvMesh& mesh, const Foam::volScalarField& field, const Foam::word& patch)
{
    const Foam::label i = mesh.boundaryMesh().findPatchID(patch);
    double sums[2] = {0, 0};
    if (i >= 0)
    {
        const Foam::scalarField& area = mesh.magSf().boundaryField()[i];
        forAll(area, f)
        {
            sums[0] += area[f]*field.boundaryField()[i][f];
            sums[1] += area[f];
        }
    }
    MPI_Allreduce(MPI_IN_PLACE, sums, 2, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    return sums[1] > 0 ? sums[0]/sums[1] : 0.0;
}

} // namespace


int CirculationCoupling::trackWidth(const Foam::dictionary& couplingDict)
{
    return couplingDict.found("circulation") ? CirculationStatistics::trackWidth : 0;
}


std::unique_ptr<CirculationCoupling> CirculationCoupling::New
(
    const Foam::fvMesh& mesh,
    const Foam::dictionary& couplingDict,
    const Foam::surfaceScalarField& phi,
    double rho
)
{
    if (!couplingDict.found("circulation")) return nullptr;
    if (!couplingDict.isDict("circulation"))
    {
        throw InputError
        (
            file + ": key 'circulation' expected a dictionary "
            "{ averageStart <s>; binWidth <s>; }"
        );
    }
    return std::unique_ptr<CirculationCoupling>
    (
        new CirculationCoupling(mesh, couplingDict, phi, rho)
    );
}


CirculationStatistics CirculationCoupling::settings
(
    const Foam::fvMesh& mesh,
    const Foam::dictionary& couplingDict,
    double& width,
    double& depth
)
{
    const Foam::dictionary& dict = couplingDict.subDict("circulation");
    double start = -1, bin = 0.05;
    if (!dict.readIfPresent("averageStart", start) || !(start >= 0))
    {
        throw InputError
        (
            file + ": key 'circulation/averageStart' expected the time [s] "
            "from which the statistics are taken, a number >= 0"
        );
    }
    if (dict.readIfPresent("binWidth", bin) && !(bin > 0))
    {
        throw InputError
        (
            file + ": key 'circulation/binWidth' expected the histogram bin "
            "width [s], a positive number"
        );
    }
    const Foam::fileName name =
        dict.getOrDefault<Foam::fileName>("geometryDict", "constant/spoutedBed");
    const Foam::fileName path = mesh.time().globalPath()/name;
    if (!Foam::isFile(path))
    {
        throw InputError
        (
            file + ": key 'circulation/geometryDict' names '" + name
          + "', which cannot be read (the draft-plate geometry, lengths in mm)"
        );
    }
    Foam::IFstream stream(path);
    const Foam::dictionary geometry(stream);
    width = lengthEntry(geometry, name, "W");
    depth = lengthEntry(geometry, name, "Lb");
    const DraftPlateRegions regions
    (
        lengthEntry(geometry, name, "Wd"), lengthEntry(geometry, name, "He"),
        lengthEntry(geometry, name, "Hd"), lengthEntry(geometry, name, "plateThickness"),
        name
    );
    const double end = mesh.time().endTime().value();
    return CirculationStatistics(regions, start, 0.5*(start + end), bin);
}


CirculationCoupling::CirculationCoupling
(
    const Foam::fvMesh& mesh,
    const Foam::dictionary& couplingDict,
    const Foam::surfaceScalarField& phi,
    double rho
)
:
    mesh_(mesh),
    phi_(phi),
    rho_(rho),
    heatModel_(couplingDict.getOrDefault<Foam::word>("heatTransferModel", "none")),
    stats_(settings(mesh, couplingDict, width_, depth_))
{
    findGasFaces();
    resume();
    const DraftPlateRegions& r = stats_.regions();
    Foam::Info<< "Circulation: statistics from t = " << stats_.averageStart()
        << " s, bins " << stats_.binWidth() << " s; spout |x| <= " << 0.5*r.Wd()
        << " m, downcomers |x| >= " << 0.5*r.Wd() + r.plateThickness()
        << " m, from z = " << r.He() << " to " << r.Hd() << " m; gas across "
        << spoutFaces_.size() << " + " << downcomerFaces_.size()
        << " faces of this rank at mid-plate height" << Foam::endl;
}


void CirculationCoupling::findGasFaces()
{
    // the horizontal internal faces of the plane nearest to a height from
    // below (on a grid whose faces fall on He and Hd, mid-plate height can
    // lie half-way between two planes): the same plane on every rank
    const DraftPlateRegions& r = stats_.regions();
    const Foam::vectorField& Cf = mesh_.faceCentres();
    const Foam::vectorField& Sf = mesh_.faceAreas();
    const auto horizontal = [&](Foam::label f)
    {
        return std::fabs(Sf[f].z()) >= 0.99*Foam::mag(Sf[f]);
    };
    const auto planeBelow = [&](double z)
    {
        double plane = -Foam::GREAT;
        for (Foam::label f = 0; f < mesh_.nInternalFaces(); ++f)
        {
            if (horizontal(f) && Cf[f].z() <= z + 1e-9) plane = std::max(plane, Cf[f].z());
        }
        MPI_Allreduce(MPI_IN_PLACE, &plane, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
        return plane;
    };
    gasHeight_ = planeBelow(0.5*(r.He() + r.Hd()));
    const double jetTop = planeBelow(r.He());
    for (Foam::label f = 0; f < mesh_.nInternalFaces(); ++f)
    {
        if (!horizontal(f)) continue;
        const double ax = std::fabs(Cf[f].x());
        if (std::fabs(Cf[f].z() - jetTop) <= 1e-9 && ax < 0.5*r.Wd()) jetTopFaces_.push_back(f);
        if (std::fabs(Cf[f].z() - gasHeight_) > 1e-9) continue;
        if (ax < 0.5*r.Wd()) spoutFaces_.push_back(f);
        else if (ax > 0.5*r.Wd() + r.plateThickness()) downcomerFaces_.push_back(f);
    }
    findCoreFaces();
}


void CirculationCoupling::findCoreFaces()
{
    // the vertical faces at |x| = Wd/2 along each core, the jet's below He,
    // the fountain core's above Hd, internal or on a processor patch (there
    // counted by the rank whose cell is in the core)
    const DraftPlateRegions& r = stats_.regions();
    const Foam::vectorField& Cf = mesh_.faceCentres();
    const Foam::vectorField& Sf = mesh_.faceAreas();
    const Foam::volVectorField& C = mesh_.C();
    const auto side = [&](Foam::label f)
    {
        if (std::fabs(Sf[f].x()) < 0.99*Foam::mag(Sf[f])
         || std::fabs(std::fabs(Cf[f].x()) - 0.5*r.Wd()) >= 1e-6*r.Wd())
        {
            return -1;
        }
        return Cf[f].z() < r.He() ? 0 : Cf[f].z() > r.Hd() ? 1 : -1;
    };
    const auto inside = [&](Foam::label cell) { return std::fabs(C[cell].x()) < 0.5*r.Wd(); };
    const Foam::labelList& owner = mesh_.faceOwner();
    for (Foam::label f = 0; f < mesh_.nInternalFaces(); ++f)
    {
        // the normal points from the owner: outward when the owner is inside
        const int core = side(f);
        if (core >= 0) coreFaces_[core].push_back({f, -1, -1, inside(owner[f]) ? 1.0 : -1.0});
    }
    forAll(mesh_.boundaryMesh(), patchi)
    {
        const Foam::polyPatch& pp = mesh_.boundaryMesh()[patchi];
        if (!pp.coupled()) continue;
        forAll(pp, i)
        {
            const int core = side(pp.start() + i);
            if (core >= 0 && inside(pp.faceCells()[i]))
            {
                coreFaces_[core].push_back({pp.start() + i, patchi, i, 1.0});
            }
        }
    }
}


void CirculationCoupling::sampleGas(const ThermalCoupling* thermal)
{
    // upward mass flows [kg/s]: the face flux along +z (its normal's sign)
    const Foam::vectorField& Sf = mesh_.faceAreas();
    // and, with the heat coupling, the T and H2O they carry from their
    // upwind cells (the mixed-cup gas through the spout gap and the
    // downcomers, beside what the kernels there see), and the same of the
    // gas leaving the jet through its top
    const Foam::volScalarField* T = thermal ? &thermal->T() : nullptr;
    const Foam::volScalarField* Y = thermal ? thermal->Y() : nullptr;
    const Foam::labelList& owner = mesh_.faceOwner();
    const Foam::labelList& neighbour = mesh_.faceNeighbour();
    double up[3] = {0, 0, 0};
    const std::vector<Foam::label>* planes[3] = {&spoutFaces_, &downcomerFaces_, &jetTopFaces_};
    for (int k = 0; k < 3; ++k)
    {
        for (const Foam::label f : *planes[k])
        {
            const double flux = phi_[f]*Foam::sign(Sf[f].z());
            up[k] += flux;
            const Foam::label from = phi_[f] > 0 ? owner[f] : neighbour[f];
            if (T) gas_[15 + 2*k] += rho_*flux*(*T)[from];
            if (Y) gas_[16 + 2*k] += rho_*flux*(*Y)[from];
        }
    }
    gas_[21] += rho_*up[2];
    const Foam::label inlet = mesh_.boundaryMesh().findPatchID("inlet");
    double in = 0;
    if (inlet >= 0) in = -Foam::sum(phi_.boundaryField()[inlet]);
    gas_[0] += rho_*in;
    gas_[1] += rho_*up[0];
    gas_[2] += rho_*up[1];
    // out of each core and into it across its sides, each time's own sign,
    // and the T and H2O each flow carries from its upwind cell (on a
    // processor patch the patch value, the neighbour rank's cell)
    const auto upwind = [&](const Foam::volScalarField& v, const CoreFace& c, bool out)
    {
        if (c.patch >= 0)
        {
            return out ? v[mesh_.boundaryMesh()[c.patch].faceCells()[c.local]]
                       : v.boundaryField()[c.patch][c.local];
        }
        const bool ownerInside = c.outward > 0;
        return v[out == ownerInside ? owner[c.face] : neighbour[c.face]];
    };
    for (std::size_t core = 0; core < coreFaces_.size(); ++core)
    {
        for (const CoreFace& c : coreFaces_[core])
        {
            const double flux = c.patch < 0 ? phi_[c.face] : phi_.boundaryField()[c.patch][c.local];
            const double out = c.outward*flux;
            const std::size_t way = out > 0 ? 0 : 1;
            const double m = rho_*std::fabs(out);
            gas_[3 + 2*core + way] += m;
            if (T) gas_[7 + 4*core + 2*way] += m*upwind(*T, c, out > 0);
            if (Y) gas_[8 + 4*core + 2*way] += m*upwind(*Y, c, out > 0);
        }
    }
}


ParticleSample CirculationCoupling::seen
(
    std::size_t k,
    const Particle& p,
    const ParticleCellMap& map,
    const std::vector<double>& eps,
    const ThermalCoupling* thermal,
    const std::vector<double>& T,
    const std::vector<double>& Y
) const
{
    const ParticleCellMap::Row row = map.cells(k);
    ParticleSample s;
    s.voidage = weighted(row, eps);
    if (!thermal) return s;
    const HeatCellCoefficients& cells = thermal->cells();
    s.slipRe = weighted(row, cells.reynolds);
    s.h = weighted(row, cells.h);
    if (!cells.km.empty()) s.km = weighted(row, cells.km);
    s.Tgas = weighted(row, T);
    if (!Y.empty()) s.Y = weighted(row, Y);
    s.Tparticle = p.temperature;
    return s;
}


void CirculationCoupling::sample
(
    const LiggghtsDem& dem,
    const std::vector<Particle>& particles,
    const ParticleCellMap& map,
    const std::vector<double>& eps,
    const FoamCellLocator& locator,
    const ThermalCoupling* thermal
)
{
    const Foam::Time& runTime = mesh_.time();
    const double dt = runTime.deltaTValue();
    const double t = double(runTime.timeIndex())*dt;
    if (t < stats_.averageStart()) return;
    const auto begin = std::chrono::steady_clock::now();
    // the gas at the particles: collective, on every rank
    std::vector<double> T, Y;
    if (thermal) T = locator.withHalo(thermal->T().primitiveField());
    if (thermal && thermal->Y()) Y = locator.withHalo(thermal->Y()->primitiveField());
    const std::vector<double*> tracks = dem.circulationTracks();
    for (std::size_t k = 0; k < particles.size(); ++k)
    {
        const Particle& p = particles[k];
        maxStep_ = std::max(maxStep_, Foam::mag(Foam::vector(p.v.x, p.v.y, p.v.z))*dt);
        stats_.observe(t, p.x, tracks[k], seen(k, p, map, eps, thermal, T, Y));
    }
    stats_.endSample(t);
    sampleGas(thermal);
    if (firstSample_ < 0) firstSample_ = t;
    lastSample_ = t;
    seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    samples_ += 1;
}


std::vector<double> CirculationCoupling::packAll() const
{
    std::vector<double> all = stats_.pack();
    all.insert(all.end(), gas_, gas_ + nGas);
    all.insert(all.end(), {maxStep_, firstSample_, lastSample_});
    return all;
}


void CirculationCoupling::unpackAll(const std::vector<double>& all)
{
    if (all.size() < extraWidth + 1)
    {
        throw InputError
        (
            "circulation state: a file of " + std::to_string(all.size())
          + " values is too short"
        );
    }
    const std::size_t n = all.size() - extraWidth;
    stats_.unpack(std::vector<double>(all.begin(), all.begin() + n));
    std::copy(all.begin() + n, all.begin() + n + nGas, gas_);
    maxStep_ = all[n + nGas];
    firstSample_ = all[n + nGas + 1];
    lastSample_ = all[n + nGas + 2];
}


void CirculationCoupling::resume()
{
    // a restart: the master takes the run's totals back, the other ranks
    // start from zero (as they do after every write time)
    const Foam::Time& runTime = mesh_.time();
    if (runTime.value() <= 0 || !Foam::Pstream::master()) return;
    const Foam::fileName state =
        runTime.globalPath()/"DEM"/("restart_" + runTime.timeName() + ".circulation");
    std::ifstream in(state, std::ios::binary);
    if (!in)
    {
        Foam::Info<< "Circulation: no statistics " << state << "; they start "
            "afresh at this restart" << Foam::endl;
        return;
    }
    std::vector<double> all;
    double v;
    while (in.read(reinterpret_cast<char*>(&v), sizeof v)) all.push_back(v);
    try
    {
        // the file's first value: a tag (negative), or in a file written
        // before the halves had batches the sampling times (not negative)
        // (a file of no sampling time, from before the window, loses none)
        const bool tagged = !all.empty() && all[0] < 0;
        batchesWhole_ = tagged ? all[0] == batchesTag : !all.empty() && all[0] == 0;
        if (tagged)
        {
            all.erase(all.begin());
        }
        else if (all.size() > extraWidth)
        {
            std::vector<double> upgraded = CirculationStatistics::withoutBatchesUpgraded
            (
                std::vector<double>(all.begin(), all.end() - extraWidth)
            );
            upgraded.insert(upgraded.end(), all.end() - extraWidth, all.end());
            all.swap(upgraded);
            if (!batchesWhole_)
            {
                Foam::Info<< "Circulation: " << state << " has the halves' moments without "
                    "their batches; circulation.json will not give batch errors" << Foam::endl;
            }
        }
        unpackAll(all);
    }
    catch (const std::exception& e)
    {
        throw InputError
        (
            std::string(state) + ": not the circulation statistics this run "
            "writes (" + e.what() + ")"
        );
    }
}


CirculationRun CirculationCoupling::runFacts
(
    const LiggghtsDem& dem,
    const std::vector<Particle>& particles,
    const ThermalCoupling* thermal
) const
{
    // n, sum d, sum V: the diameter is an original particle's, the count
    // and the mass (what the statistics' counts weigh) the DEM particles'
    double sums[3] = {double(particles.size()), 0, 0};
    for (const Particle& p : particles)
    {
        sums[1] += p.diameter();
        sums[2] += p.volume();
    }
    const std::vector<double>* dry = thermal ? thermal->dryMass() : nullptr;
    double dryMass = 0;
    if (dry) for (const double m : *dry) dryMass += m;
    double all[4] = {sums[0], sums[1], sums[2], dryMass};
    MPI_Allreduce(MPI_IN_PLACE, all, 4, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    CirculationRun run;
    run.particles = all[0];
    const double n = std::max(all[0], 1.0);
    run.diameter = all[1]/n;
    const double mass = dem.totalMass();
    run.density = all[2] > 0 ? mass/all[2] : 0.0;
    run.mass = dry ? all[3]/n : mass/n;
    if (thermal)
    {
        run.inletTemperature = patchMean(mesh_, thermal->T(), "inlet");
        if (thermal->Y())
        {
            const double Y = patchMean(mesh_, *thermal->Y(), "inlet");
            run.inletHumidityRatio = Y/(1 - Y);
        }
    }
    return run;
}


std::size_t CirculationCoupling::appendOpenVisits
(
    const LiggghtsDem& dem,
    std::vector<double>& all
) const
{
    // their time in the window per state (the boundary term of Little's
    // law), then by their time so far per distribution, in as many bins as
    // the window holds (the same on every rank)
    const double dt = mesh_.time().deltaTValue();
    if (lastSample_ < 0)
    {
        all.resize(all.size() + nCirculationRegions + censoredEnd_.size(), 0.0);
        return 1;
    }
    const std::array<double, nCirculationRegions> open =
        CirculationStatistics::openAtEnd(dem.circulationTracks(), lastSample_, dt);
    all.insert(all.end(), open.begin(), open.end());
    const std::size_t bins =
        std::size_t((lastSample_ - stats_.averageStart() + dt)/stats_.binWidth() + 1e-9) + 1;
    for
    (
        const std::vector<double>& h
      : CirculationStatistics::censoredAtEnd
        (
            dem.circulationTracks(), lastSample_, dt, stats_.binWidth(), bins
        )
    )
    {
        all.insert(all.end(), h.begin(), h.end());
    }
    return bins;
}


std::vector<double>::iterator CirculationCoupling::takeOpenVisits
(
    std::vector<double>& total,
    std::size_t bins
)
{
    auto h = total.end() - std::ptrdiff_t(censoredEnd_.size()*bins);
    const auto open = h - nCirculationRegions;
    std::copy(open, h, openEnd_.begin());
    for (std::vector<double>& censored : censoredEnd_)
    {
        censored.assign(h, h + std::ptrdiff_t(bins));
        h += std::ptrdiff_t(bins);
    }
    return open;
}


void CirculationCoupling::write
(
    const LiggghtsDem& dem,
    const std::vector<Particle>& particles,
    const ThermalCoupling* thermal,
    bool stateFile
)
{
    const CirculationRun run = runFacts(dem, particles, thermal);
    // the sums to the master, which keeps the totals; the others go on
    // from zero, so a restart (the totals back on the master) adds the same
    unsigned long bins = stats_.bins();
    MPI_Allreduce(MPI_IN_PLACE, &bins, 1, MPI_UNSIGNED_LONG, MPI_MAX, MPI_COMM_WORLD);
    std::vector<double> all = stats_.pack(bins, Foam::Pstream::master());
    all.insert(all.end(), gas_, gas_ + nGas);
    // the visits open at the last sample, from the tracks: not sums kept
    const std::size_t censoredBins = appendOpenVisits(dem, all);
    std::vector<double> total(all.size());
    MPI_Reduce(all.data(), total.data(), int(all.size()), MPI_DOUBLE, MPI_SUM, 0, MPI_COMM_WORLD);
    MPI_Allreduce(MPI_IN_PLACE, &maxStep_, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    if (!Foam::Pstream::master())
    {
        stats_.clear();
        std::fill(gas_, gas_ + nGas, 0.0);
        return;
    }
    const auto tail = takeOpenVisits(total, censoredBins);
    stats_.unpack(std::vector<double>(total.begin(), tail - nGas));
    std::copy(tail - nGas, tail, gas_);
    if (stateFile)
    {
        const Foam::Time& runTime = mesh_.time();
        const std::string state =
            runTime.globalPath()/"DEM"/("restart_" + runTime.timeName() + ".circulation");
        std::vector<double> values = packAll();
        values.insert(values.begin(), batchesWhole_ ? batchesTag : partBatchesTag);
        std::ofstream out(state, std::ios::binary);
        out.write
        (
            reinterpret_cast<const char*>(values.data()),
            std::streamsize(values.size()*sizeof(double))
        );
    }
    writeJson(run);
}


std::string CirculationCoupling::runJson(const CirculationRun& run) const
{
    const DraftPlateRegions& r = stats_.regions();
    const Foam::Time& runTime = mesh_.time();
    const double n = std::max(stats_.sampleTimes(), 1.0);
    const double us = gas_[0]/rho_/n/(width_*depth_);
    std::ostringstream j;
    j << "{\"case\": \"" << std::string(runTime.globalCaseName()) << "\", \"u_s\": " << number(us)
      << ", \"particles\": " << number(run.particles) << ", \"particleDiameter\": " << number(run.diameter)
      << ", \"particleDensity\": " << number(run.density) << ", \"particleMass\": " << number(run.mass)
      << ", \"heatTransferModel\": \"" << heatModel_ << "\", \"inletTemperature\": "
      << number(run.inletTemperature) << ", \"inletHumidityRatio\": " << number(run.inletHumidityRatio)
      << ",\n    \"geometry\": {\"Wd\": " << number(r.Wd()) << ", \"He\": " << number(r.He())
      << ", \"Hd\": " << number(r.Hd()) << ", \"plateThickness\": " << number(r.plateThickness())
      << ", \"width\": " << number(width_) << ", \"depth\": " << number(depth_) << "},\n    "
      << "\"timeStart\": " << number(firstSample_) << ", \"timeEnd\": " << number(lastSample_)
      << ", \"samplingInterval\": " << number(runTime.deltaTValue()) << ", \"averageStart\": "
      << number(stats_.averageStart()) << ", \"sampleTimes\": " << number(stats_.sampleTimes())
      << ", \"window\": " << number(stats_.sampleTimes()*runTime.deltaTValue())
      << ", \"maxStepDisplacement\": " << number(maxStep_) << ", \"skippedSamples\": "
      << number(stats_.skippedSamples()) << "}";
    return j.str();
}


std::string CirculationCoupling::residenceJson() const
{
    std::string all = "{", halves[2] = {"{", "{"}, batches[2] = {"{", "{"};
    for (int i = 0; i <= CirculationStatistics::cycle; ++i)
    {
        const ResidenceDistribution& d = stats_.residence(i);
        const std::string key = (i ? ",\n    \"" : "\n    \"") + distributionName(i) + "\": ";
        all += key + residenceEntry(d, stats_.binWidth(), censoredEnd_[std::size_t(i)]);
        for (int h = 0; h < 2; ++h)
        {
            halves[h] += key + moments(d.half(h));
            std::vector<double> samples, sums;
            for (int b = 0; b < ResidenceDistribution::batchesPerHalf; ++b)
            {
                const Moments& m = d.batches[std::size_t(h*ResidenceDistribution::batchesPerHalf + b)];
                samples.push_back(m.samples);
                sums.push_back(m.sum);
            }
            batches[h] += key + "{\"samples\": " + countList(samples) + ", \"sum\": "
                + countList(sums) + "}";
        }
    }
    std::string j = "\"residence\": " + all + "},\n  \"halves\": {\"first\": " + halves[0]
        + "},\n  \"second\": " + halves[1] + "}}";
    // a run resumed from statistics without batches has them only in part
    if (batchesWhole_)
    {
        j += ",\n  \"batches\": {\"first\": " + batches[0] + "},\n  \"second\": "
            + batches[1] + "}}";
    }
    return j;
}


std::string CirculationCoupling::conditionsJson() const
{
    static const char* const names[nSampleQuantities] =
        {"voidage", "slipRe", "h", "km", "Tgas", "Y", "Tparticle"};
    // holdup and the means of what the particles saw, mean(q) of quantity q
    const auto seenJson = [](double holdup, const auto& mean)
    {
        std::string j = "\"holdup\": " + number(holdup);
        for (int q = 0; q < nSampleQuantities; ++q)
        {
            j += std::string(", \"") + names[q] + "\": " + number(mean(q));
        }
        return j + ", \"humidityRatio\": " + number(mean(5)/(1 - mean(5)));
    };
    const double window = std::max(stats_.sampleTimes(), 1.0)*mesh_.time().deltaTValue();
    std::string j = "\"conditions\": {";
    for (int s = 0; s < nCirculationRegions; ++s)
    {
        j += std::string(s ? "," : "") + "\n    \"" + circulationRegionName(s) + "\": {"
            + seenJson(stats_.holdup(s), [&](int q) { return stats_.meanSeen(s, q); })
            + ", \"entries\": "
            + number(stats_.entries(s)) + ", \"entryRate\": " + number(stats_.entries(s)/window)
            + ", \"occupancy\": " + number(stats_.holdup(s)*window) + ", \"completed\": "
            + number(stats_.residence(s).all.sum) + ", \"openAtStart\": "
            + number(stats_.openAtStart(s)) + ", \"openAtEnd\": " + number(openEnd_[s]);
        if (CirculationStatistics::coreOf(s) >= 0)
        {
            std::string counts;
            for (const double n : stats_.coreFractions(s))
            {
                counts += (counts.empty() ? "" : ", ") + number(n);
            }
            j += std::string(",\n      \"") + (s == entrainmentRegion ? "jet" : "core") + "\": {"
                + seenJson(stats_.coreHoldup(s), [&](int q) { return stats_.meanSeenInCore(s, q); })
                + ",\n        \"visitFractions\": {\"binWidth\": "
                + number(1.0/CirculationStatistics::nCoreFractionBins) + ", \"counts\": ["
                + counts + "]}}";
        }
        j += "}";
    }
    return j + "}";
}


std::string CirculationCoupling::carriedJson() const
{
    // the flow-weighted T [K] and H2O mass fraction of the gas each of the
    // four side flows carries, and of the net upward flows through the
    // spout gap and the downcomers and out of the jet's top (the plane of
    // faces nearest to He from below, |x| < Wd/2); nothing without the heat
    // coupling
    static const char* const names[7] = {"outOfJet", "intoJet", "outOfFountainCore",
        "intoFountainCore", "spoutGap", "downcomers", "jetTop"};
    std::string j;
    for (int k = 0; k < 7; ++k)
    {
        const double m = k < 4 ? gas_[3 + k] : k < 6 ? gas_[k - 3] : gas_[21];
        const double mT = gas_[7 + 2*k], mY = gas_[8 + 2*k];
        if (!(m > 0 && mT > 0)) continue;
        j += std::string(j.empty() ? "" : ", ") + "\"" + names[k] + "\": {\"T\": "
            + number(mT/m) + (mY > 0 ? ", \"H2O\": " + number(mY/m) : "") + "}";
    }
    return j.empty() ? j : ",\n    \"carried\": {" + j + "}";
}


void CirculationCoupling::writeJson(const CirculationRun& run) const
{
    const double n = std::max(stats_.sampleTimes(), 1.0);
    const double window = n*mesh_.time().deltaTValue();
    const double in = gas_[0]/n;
    const auto share = [&](double sum) { return in != 0 ? sum/n/in : 0.0; };
    std::ostringstream j;
    j << "{\n  \"format\": \"spoutlab-circulation 1\",\n  \"run\": " << runJson(run)
      << ",\n  \"regions\": [\"spout\", \"fountain\", \"downcomer\", \"entrainment\"],\n  "
      << residenceJson() << ",\n  " << conditionsJson() << ",\n  \"gas\": {\"inletMassFlow\": "
      << number(in) << ", \"height\": " << number(gasHeight_) << ", \"spoutShare\": "
      << number(share(gas_[1])) << ", \"downcomerShare\": "
      << number(share(gas_[2])) << ", \"outOfJet\": " << number(share(gas_[3]))
      << ", \"intoJet\": " << number(share(gas_[4])) << ",\n    \"outOfFountainCore\": "
      << number(share(gas_[5])) << ", \"intoFountainCore\": " << number(share(gas_[6]))
      << carriedJson() << "},\n  \"circulationRate\": "
      << number(stats_.entries(spoutRegion)/window*run.mass) << "\n}\n";
    const std::string path = mesh_.time().globalPath()/"circulation.json";
    {
        std::ofstream out(path + ".tmp");
        out << j.str();
        if (!out.flush()) throw InputError("cannot write " + path + ".tmp");
    }
    if (std::rename((path + ".tmp").c_str(), path.c_str()) != 0)
    {
        throw InputError("cannot rename " + path + ".tmp to circulation.json");
    }
}


void CirculationCoupling::report() const
{
    double cost[2] = {seconds_, samples_};
    MPI_Allreduce(MPI_IN_PLACE, cost, 2, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    Foam::Info<< "Circulation: " << cost[1] << " sampling times, "
        << 1e3*cost[0]/std::max(cost[1], 1.0) << " ms each (the slowest rank), "
        << cost[0] << " s in all" << Foam::endl;
}

} // namespace spoutlab
