/*---------------------------------------------------------------------------*\
    SpoutLab: the in-process LIGGGHTS instance owned by spoutFoam.
\*---------------------------------------------------------------------------*/
#include "LiggghtsDem.H"

#include "InputError.hpp"
#include "LiggghtsInputCheck.H"
#include "RankGather.H"

#include "atom.h"
#include "atom_vec.h"
#include "comm.h"
#include "domain.h"
#include "fix_property_atom.h"
#include "fix_property_global.h"
#include "input.h"
#include "irregular.h"
#include "lammps.h"
#include "modify.h"
#include "neighbor.h"
#include "update.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <utility>

namespace spoutlab
{

namespace
{

// LIGGGHTS stops the whole program with exit(1) on an error and writes the
// reason only to its log.  Remember what we asked it to do and, if it stops,
// repeat its ERROR line on stderr so the user sees one clear line.
std::string liggghtsActivity;
std::string liggghtsLog;

void reportLiggghtsStop()
{
    if (liggghtsActivity.empty()) return;
    std::string reason = "see " + liggghtsLog;
    std::ifstream log(liggghtsLog);
    for (std::string line; std::getline(log, line);)
    {
        if (line.rfind("ERROR", 0) == 0) reason = line;
    }
    std::cerr << "spoutFoam: LIGGGHTS stopped while " << liggghtsActivity
              << ": " << reason << std::endl;
}

class Activity
{
public:
    explicit Activity(const std::string& what) { liggghtsActivity = what; }
    ~Activity() { liggghtsActivity.clear(); }
};

bool readable(const std::string& path)
{
    std::ifstream f(path);
    return f.good();
}


// LIGGGHTS' command line: LIGGGHTS 3.8.0 writes to its screen
// unconditionally in places (crash with -screen none), so its screen output
// goes to the log file; the variables as -var name value.
std::vector<std::string> commandLine
(
    const std::map<std::string, std::string>& variables,
    const std::string& logFile
)
{
    std::vector<std::string> args =
        {"liggghts", "-log", "none", "-screen", logFile, "-echo", "none"};
    for (const auto& v : variables)
    {
        args.insert(args.end(), {"-var", v.first, v.second});
    }
    return args;
}

} // namespace


LiggghtsDem::LiggghtsDem
(
    const std::string& inputFile,
    const std::map<std::string, std::string>& variables,
    const std::string& logFile,
    MPI_Comm comm,
    int moistureState,
    int circulationTrack
)
:
    lmp_(nullptr),
    dragForce_(nullptr),
    temperature_(nullptr),
    convectiveHeatFlux_(nullptr),
    comm_(comm),
    stepsRun_(0)
{
    if (!readable(inputFile))
    {
        throw InputError
        (
            "LIGGGHTS input '" + inputFile + "' cannot be read (missing file?)"
        );
    }

    checkIncludes(inputFile, variables);

    std::vector<std::string> args = commandLine(variables, logFile);
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(&a[0]);

    static bool registered = false;
    if (!registered)
    {
        std::atexit(reportLiggghtsStop);
        registered = true;
    }
    liggghtsLog = logFile;

    {
        Activity doing("reading input '" + inputFile + "'");
        lmp_ = new LAMMPS_NS::LAMMPS(int(argv.size()), argv.data(), comm);
        // unbuffered, so an ERROR line is in the log even when LIGGGHTS
        // ends with MPI_Abort (error->one), which flushes nothing
        if (lmp_->screen) std::setvbuf(lmp_->screen, nullptr, _IONBF, 0);
        lmp_->input->file(inputFile.c_str());
    }
    findCouplingFixes(inputFile);
    findHeatFixes(inputFile);
    if (moistureState >= 0) declareMoisture(inputFile, moistureState);
    if (circulationTrack > 0) declareCirculationTrack(circulationTrack);
    int nProcs = 1;
    MPI_Comm_size(comm_, &nProcs);
    if (nProcs == 1)
    {
        Activity doing("setting up the DEM run");
        setup();
    }
}


LiggghtsDem::~LiggghtsDem()
{
    delete lmp_;
}


void LiggghtsDem::findCouplingFixes(const std::string& inputFile)
{
    using namespace LAMMPS_NS;
    dragForce_ = static_cast<FixPropertyAtom*>
    (
        lmp_->modify->find_fix_property
        (
            "dragforce", "property/atom", "vector", 0, 0, "spoutFoam", false
        )
    );
    if (!dragForce_ || !lmp_->modify->find_fix_style_strict("couple/cfd", 0))
    {
        throw InputError
        (
            "LIGGGHTS input '" + inputFile + "': expected the coupling fixes "
            "'fix ID all couple/cfd couple_every 0 mpi' and "
            "'fix ID all couple/cfd/force'"
        );
    }
    if (lmp_->atom->radius == nullptr || lmp_->atom->rmass == nullptr)
    {
        throw InputError
        (
            "LIGGGHTS input '" + inputFile
          + "': expected 'atom_style granular' (spheres with radius and mass)"
        );
    }
    if (lmp_->atom->map_style == 0)
    {
        throw InputError
        (
            "LIGGGHTS input '" + inputFile + "': expected 'atom_modify map array' "
            "before the box is defined (the coupling looks particles up by id)"
        );
    }
}


void LiggghtsDem::findHeatFixes(const std::string& inputFile)
{
    using namespace LAMMPS_NS;
    auto* modify = lmp_->modify;
    convectiveHeatFlux_ = static_cast<FixPropertyAtom*>
    (
        modify->find_fix_property
        (
            "convectiveHeatFlux", "property/atom", "scalar", 0, 0, "spoutFoam",
            false
        )
    );
    if (!convectiveHeatFlux_) return;

    temperature_ = static_cast<FixPropertyAtom*>
    (
        modify->find_fix_property
        (
            "Temp", "property/atom", "scalar", 0, 0, "spoutFoam", false
        )
    );
    const int nTypes = lmp_->atom->ntypes;
    auto* capacity = static_cast<FixPropertyGlobal*>
    (
        modify->find_fix_property
        (
            "thermalCapacity", "property/global", "peratomtype", nTypes, 0,
            "spoutFoam", false
        )
    );
    if (!temperature_ || !capacity)
    {
        throw InputError
        (
            "LIGGGHTS input '" + inputFile + "': 'fix couple/cfd/convection' "
            "expects 'fix ID all property/global thermalCapacity peratomtype "
            "c_1 ... c_n' [J/kg/K] for the particle temperatures"
        );
    }
    heatCapacity_.resize(nTypes);
    for (int t = 0; t < nTypes; ++t)
    {
        heatCapacity_[t] = capacity->compute_vector(t);
        if (!(heatCapacity_[t] > 0))
        {
            throw InputError
            (
                "LIGGGHTS input '" + inputFile + "': thermalCapacity of atom "
                "type " + std::to_string(t + 1) + " expected a positive heat "
                "capacity [J/kg/K], got " + std::to_string(heatCapacity_[t])
            );
        }
    }
}


void LiggghtsDem::declareMoisture(const std::string& inputFile, int stateSize)
{
    using namespace LAMMPS_NS;
    auto* modify = lmp_->modify;
    moisture_ = static_cast<FixPropertyAtom*>
    (
        modify->find_fix_property
        (
            "moisture", "property/atom", "scalar", 0, 0, "spoutFoam", false
        )
    );
    if (!moisture_ || !hasHeat())
    {
        throw InputError
        (
            "LIGGGHTS input '" + inputFile + "': drying (dryingModel in "
            "constant/couplingProperties) expects the particle moisture of "
            "'fix ID all property/atom moisture scalar yes no no <X0>' [kg "
            "water/kg dry solid] and the particle temperatures of "
            "'fix ID all couple/cfd/convection'"
        );
    }
    // what the coupling keeps per atom beside X: declared after the input
    // read its restart, so a restarted run gets its values back (the same
    // fix ids, styles and sizes; restart yes, no ghost communication)
    command("fix spoutFoamDryMass all property/atom dryMass scalar yes no no 0");
    dryMass_ = static_cast<FixPropertyAtom*>
    (
        modify->find_fix_property("dryMass", "property/atom", "scalar", 0, 0, "spoutFoam")
    );
    if (stateSize > 0)
    {
        std::string cmd =
            "fix spoutFoamMoistureState all property/atom moistureState vector yes no no";
        for (int k = 0; k < stateSize; ++k) cmd += " 0";
        command(cmd);
        moistureState_ = static_cast<FixPropertyAtom*>
        (
            modify->find_fix_property
            (
                "moistureState", "property/atom", "vector", stateSize, 0, "spoutFoam"
            )
        );
    }
    moistureStateSize_ = stateSize;
    // the masses change between runs: LIGGGHTS then sends them to the ghost
    // atoms every step (else a contact across a rank boundary sees the mass
    // of the last re-neighbouring)
    dryMass_->rad_mass_vary_flag = 1;
}


void LiggghtsDem::declareCirculationTrack(int width)
{
    // like the dry mass: declared after the input read its restart, so a
    // restarted run gets the tracks back; -1 marks an atom not yet seen
    std::string cmd = "fix spoutFoamCirculation all property/atom circulationTrack vector yes no no";
    for (int k = 0; k < width; ++k) cmd += " -1";
    command(cmd);
    circulationTrack_ = static_cast<LAMMPS_NS::FixPropertyAtom*>
    (
        lmp_->modify->find_fix_property
        (
            "circulationTrack", "property/atom", "vector", width, 0, "spoutFoam"
        )
    );
}


std::vector<double*> LiggghtsDem::circulationTracks() const
{
    if (!circulationTrack_) throw std::logic_error("LiggghtsDem: no circulation tracks declared");
    const std::vector<int>& atoms = localAtoms();
    std::vector<double*> rows(atoms.size());
    double** tracks = circulationTrack_->array_atom;
    for (std::size_t k = 0; k < atoms.size(); ++k) rows[k] = tracks[atoms[k]];
    return rows;
}


void LiggghtsDem::run(int nSteps)
{
    Activity doing("running " + std::to_string(nSteps) + " DEM steps");
    const std::string cmd = "run " + std::to_string(nSteps) + " pre no post no";
    // LIGGGHTS zeroes its count at every set-up and restart write: count
    // the builds of each run here
    const long before = long(lmp_->neighbor->ncalls);
    localAtoms_.clear();
    lmp_->input->one(cmd.c_str());
    neighbourBuilds_ += long(lmp_->neighbor->ncalls) - before;
    stepsRun_ += nSteps;
}


void LiggghtsDem::setup()
{
    // A run's set-up (its 'pre' phase) zeroes the per-atom properties the
    // coupling pulls from the CFD side -- dragforce and convectiveHeatFlux --
    // so it runs before they are set: a 'run N' with set-up would start its
    // N steps with no fluid force and no heat flux.
    // A set-up also sorts the atoms in space, from the order they are in,
    // and the particles come in that order (localParticles), which sets the
    // order of every sum over them.  A restarted run's set-up would sort the
    // restart's atoms and the running solver's its own, so the two would
    // part at round-off: the set-up leaves the atoms where they are, and
    // both sort next at the same step, the first multiple of the sort
    // interval after it (LIGGGHTS sorts again within its runs).
    auto* atom = lmp_->atom;
    const int sortInterval = atom->sortfreq;
    atom->sortfreq = 0;
    localAtoms_.clear();
    lmp_->input->one("run 0 post no");
    atom->sortfreq = sortInterval;
    if (sortInterval > 0)
    {
        atom->setup();   // the sort's bins, which a set-up without sorting leaves
        atom->nextsort = (lmp_->update->ntimestep/sortInterval + 1)*sortInterval;
    }
}


long LiggghtsDem::neighbourBuilds() const
{
    return neighbourBuilds_;
}


double LiggghtsDem::skin() const
{
    return lmp_->neighbor->skin;
}


double LiggghtsDem::timeStep() const
{
    return lmp_->update->dt;
}


double LiggghtsDem::time() const
{
    return stepsRun_*timeStep();
}


long LiggghtsDem::step() const
{
    return stepsRun_;
}


void LiggghtsDem::localParticles(std::vector<Particle>& particles)
{
    const auto* atom = lmp_->atom;
    const double* T = hasHeat() ? temperature_->vector_atom : nullptr;

    // In LIGGGHTS' own order (it sorts its atoms in space every so often,
    // and atoms move between ranks at re-neighbouring), so that every copy
    // to and from the atoms reads and writes their arrays in sequence; a
    // particle keeps its place, and its cell and row (VoidFractionModel),
    // between the sorts, and is found by its id across them.
    const int nLocal = atom->nlocal;
    std::vector<int> order(static_cast<std::size_t>(nLocal));
    for (int i = 0; i < nLocal; ++i) order[std::size_t(i)] = i;

    particles.resize(order.size());
    localIds_.resize(order.size());
    for (std::size_t k = 0; k < order.size(); ++k)
    {
        const int i = order[k];
        Particle& p = particles[k];
        p.id = atom->tag[i];
        p.x = Vec3{atom->x[i][0], atom->x[i][1], atom->x[i][2]};
        p.v = Vec3{atom->v[i][0], atom->v[i][1], atom->v[i][2]};
        p.radius = atom->radius[i];
        p.temperature = T ? T[i] : 0.0;
        p.coarseGraining = coarseGraining_;
        localIds_[k] = p.id;
    }
    localAtoms_ = std::move(order);
}


template<class Store>
void LiggghtsDem::toAtoms(const std::vector<double>& rows, int width, Store store)
{
    if (rows.size() != std::size_t(width)*localIds_.size())
    {
        throw std::logic_error("LiggghtsDem: per-particle data differs from localParticles");
    }
    const std::vector<int>& atoms = localAtoms();
    for (std::size_t k = 0; k < atoms.size(); ++k) store(atoms[k], &rows[std::size_t(width)*k]);
}


void LiggghtsDem::setFluidForces(const std::vector<Vec3>& forces)
{
    std::vector<double> rows(3*forces.size());
    for (std::size_t i = 0; i < forces.size(); ++i)
    {
        rows[3*i] = forces[i].x;
        rows[3*i + 1] = forces[i].y;
        rows[3*i + 2] = forces[i].z;
    }
    double** drag = dragForce_->array_atom;
    toAtoms
    (
        rows, 3,
        [drag](int i, const double* f) { for (int d = 0; d < 3; ++d) drag[i][d] = f[d]; }
    );
}


void LiggghtsDem::setHeatFluxes(const std::vector<double>& q)
{
    double* flux = convectiveHeatFlux_->vector_atom;
    toAtoms(q, 1, [flux](int i, const double* qi) { flux[i] = *qi; });
}


LiggghtsDem::HeatContent LiggghtsDem::heatContent() const
{
    const auto* atom = lmp_->atom;
    const double* T = temperature_->vector_atom;
    double sums[2] = {0, 0};   // m c_p T, m c_p
    for (int i = 0; i < atom->nlocal; ++i)
    {
        const double C = atom->rmass[i]*heatCapacity_[atom->type[i] - 1];
        sums[0] += C*T[i];
        sums[1] += C;
    }
    MPI_Allreduce(MPI_IN_PLACE, sums, 2, MPI_DOUBLE, MPI_SUM, comm_);
    return HeatContent{sums[0], sums[1]};
}


const std::vector<int>& LiggghtsDem::localAtoms() const
{
    if (localAtoms_.size() == localIds_.size()) return localAtoms_;
    // LIGGGHTS ran since localParticles: the atom map (atom_modify map
    // array, required of coupled inputs)
    auto* atom = lmp_->atom;
    std::vector<int> atoms(localIds_.size());
    for (std::size_t k = 0; k < localIds_.size(); ++k)
    {
        const int i = atom->map(int(localIds_[k]));
        if (i < 0 || i >= atom->nlocal)
        {
            throw std::logic_error("LiggghtsDem: an atom left this rank between steps");
        }
        atoms[k] = i;
    }
    localAtoms_ = std::move(atoms);
    return localAtoms_;
}


std::vector<std::size_t> LiggghtsDem::localMoisture(KernelMoisture& kernels) const
{
    std::vector<std::size_t> fresh;
    auto* atom = lmp_->atom;
    const std::size_t n = localIds_.size(), width = std::size_t(moistureStateSize_);
    const std::vector<int>& atoms = localAtoms();
    kernels.dryMass.resize(n);
    kernels.moisture.resize(n);
    // the state stays in the atoms' rows, used there until setMoisture
    kernels.state.clear();
    kernels.stateRows.assign(width ? n : 0, nullptr);
    const double* X = moisture_->vector_atom;
    const double* md = dryMass_->vector_atom;
    double* const* state = width ? moistureState_->array_atom : nullptr;
    for (std::size_t k = 0; k < n; ++k)
    {
        const int i = atoms[k];
        kernels.moisture[k] = X[i];
        kernels.dryMass[k] = md[i];
        if (!(kernels.dryMass[k] > 0))
        {
            kernels.dryMass[k] = atom->rmass[i]/(1 + kernels.moisture[k]);
            fresh.push_back(k);
        }
        if (width) kernels.stateRows[k] = state[i];
    }
    return fresh;
}


void LiggghtsDem::setMoisture(const KernelMoisture& kernels, const Vec3& g)
{
    const std::size_t n = localIds_.size(), width = std::size_t(moistureStateSize_);
    if
    (
        kernels.moisture.size() != n || kernels.dryMass.size() != n
     || (width && kernels.stateRows.size() != n)
    )
    {
        throw std::logic_error("LiggghtsDem: per-particle data differs from localParticles");
    }
    const std::vector<int>& atoms = localAtoms();
    auto* atom = lmp_->atom;
    double* X = moisture_->vector_atom;
    double* md = dryMass_->vector_atom;
    double* const* state = width ? moistureState_->array_atom : nullptr;
    double* rmass = atom->rmass;
    double* density = atom->density;
    const double* radius = atom->radius;
    double** f = atom->f;
    for (std::size_t k = 0; k < n; ++k)
    {
        const int i = atoms[k];
        const double x = kernels.moisture[k], dry = kernels.dryMass[k];
        X[i] = x;
        md[i] = dry;
        // the state was stepped in the atom's row (localMoisture)
        if (width && kernels.stateRows[k] != state[i])
        {
            throw std::logic_error("LiggghtsDem: an atom's moisture state moved between steps");
        }
        const double m = dry*(1 + x);
        const double dm = m - rmass[i];
        f[i][0] += dm*g.x;
        f[i][1] += dm*g.y;
        f[i][2] += dm*g.z;
        rmass[i] = m;
        const double r3 = radius[i]*radius[i]*radius[i];
        density[i] = m/(4.0/3.0*3.14159265358979323846*r3);
    }
}


std::vector<double> LiggghtsDem::liggghtsHeatCapacities() const
{
    auto* atom = lmp_->atom;
    const std::vector<int>& atoms = localAtoms();
    std::vector<double> C(atoms.size());
    for (std::size_t k = 0; k < atoms.size(); ++k)
    {
        const int i = atoms[k];
        C[k] = atom->rmass[i]*heatCapacity_[atom->type[i] - 1];
    }
    return C;
}


double LiggghtsDem::minHeatCapacityPerArea() const
{
    const auto* atom = lmp_->atom;
    const double pi = 3.14159265358979323846;
    double cMin = 1e300;
    for (int i = 0; i < atom->nlocal; ++i)
    {
        const double r = atom->radius[i];
        const double c = atom->rmass[i]*heatCapacity_[atom->type[i] - 1];
        // a parcel exchanges through its originals' surface, cg times its own
        cMin = std::min(cMin, c/(4*pi*r*r*coarseGraining_));
    }
    MPI_Allreduce(MPI_IN_PLACE, &cMin, 1, MPI_DOUBLE, MPI_MIN, comm_);
    return cMin;
}


void LiggghtsDem::deleteParticles(const std::vector<long>& ids)
{
    if (ids.empty()) return;
    Activity doing("deleting particles outside the CFD mesh");
    std::string group = "group spoutFoamLost id";
    for (long id : ids) group += " " + std::to_string(id);
    command(group);
    // compress no: the others keep their ids, as in the particle files
    // written so far and whatever the decomposition (compress renumbers
    // them rank by rank)
    command("delete_atoms group spoutFoamLost compress no");
    command("group spoutFoamLost delete");
    // LIGGGHTS 3.8 refuses a set-up without atoms ("Atom types must start
    // from 1"); with none left there are no neighbour lists to rebuild
    if (nParticles() > 0) setup();
}


long LiggghtsDem::nParticles() const
{
    long n = lmp_->atom->nlocal;
    MPI_Allreduce(MPI_IN_PLACE, &n, 1, MPI_LONG, MPI_SUM, comm_);
    return n;
}


double LiggghtsDem::reach() const
{
    double rMax = 0;
    for (int i = 0; i < lmp_->atom->nlocal; ++i) rMax = std::max(rMax, lmp_->atom->radius[i]);
    MPI_Allreduce(MPI_IN_PLACE, &rMax, 1, MPI_DOUBLE, MPI_MAX, comm_);
    return rMax + lmp_->neighbor->skin;
}


double LiggghtsDem::totalMass() const
{
    double m = 0;
    for (int i = 0; i < lmp_->atom->nlocal; ++i) m += lmp_->atom->rmass[i];
    MPI_Allreduce(MPI_IN_PLACE, &m, 1, MPI_DOUBLE, MPI_SUM, comm_);
    return m;
}


double LiggghtsDem::minParticleMass() const
{
    double mMin = 1e300;
    for (int i = 0; i < lmp_->atom->nlocal; ++i)
    {
        mMin = std::min(mMin, lmp_->atom->rmass[i]);
    }
    MPI_Allreduce(MPI_IN_PLACE, &mMin, 1, MPI_DOUBLE, MPI_MIN, comm_);
    return mMin;
}


double LiggghtsDem::maxNormalStiffness() const
{
    using namespace LAMMPS_NS;
    auto* kn = static_cast<FixPropertyGlobal*>
    (
        lmp_->modify->find_fix_property
        (
            "kn", "property/global", "peratomtypepair", 0, 0, "spoutFoam", false
        )
    );
    if (!kn) return 0;
    // peratomtypepair: an ntypes x ntypes matrix
    const int nTypes = lmp_->atom->ntypes;
    double kMax = 0;
    for (int i = 0; i < nTypes; ++i)
    {
        for (int j = 0; j < nTypes; ++j)
        {
            kMax = std::max(kMax, kn->compute_array(i, j));
        }
    }
    return kMax;
}


void LiggghtsDem::command(const std::string& cmd)
{
    localAtoms_.clear();
    lmp_->input->one(cmd.c_str());
}


bool LiggghtsDem::onGrid(const ProcessorGrid& grid) const
{
    const auto* comm = lmp_->comm;
    int me = 0;
    MPI_Comm_rank(comm_, &me);
    int same = 1;
    for (int a = 0; a < 3; ++a)
    {
        same = same && comm->procgrid[a] == grid.n[a]
            && comm->myloc[a] == grid.box[std::size_t(me)][a];
    }
    MPI_Allreduce(MPI_IN_PLACE, &same, 1, MPI_INT, MPI_MIN, comm_);
    return same == 1;
}


void LiggghtsDem::regrid(const ProcessorGrid& grid)
{
    // LIGGGHTS' own grid of that shape (its arrays and splits), then each
    // rank's place and neighbours taken from the mesh's boxes, as
    // LIGGGHTS' map would have put them (its neighbours wrap around)
    auto* comm = lmp_->comm;
    for (int a = 0; a < 3; ++a) comm->user_procgrid[a] = grid.n[a];
    comm->set_proc_grid(0);
    int me = 0;
    MPI_Comm_rank(comm_, &me);
    for (int i = 0; i < grid.n[0]; ++i)
    {
        for (int j = 0; j < grid.n[1]; ++j)
        {
            for (int k = 0; k < grid.n[2]; ++k)
            {
                comm->grid2proc[i][j][k] = grid.rankAt({{i, j, k}});
            }
        }
    }
    const std::array<int, 3>& mine = grid.box[std::size_t(me)];
    for (int a = 0; a < 3; ++a)
    {
        comm->myloc[a] = mine[a];
        for (int side = 0; side < 2; ++side)
        {
            std::array<int, 3> next = mine;
            next[a] = (mine[a] + (side ? 1 : -1) + grid.n[a]) % grid.n[a];
            comm->procneigh[a][side] = grid.rankAt(next);
        }
    }
}


void LiggghtsDem::setDecomposition(const ProcessorGrid& grid)
{
    Activity doing("setting up the DEM run");
    auto* comm = lmp_->comm;
    auto* domain = lmp_->domain;
    const bool moved = !onGrid(grid);
    if (moved) regrid(grid);
    else setup();   // on LIGGGHTS' own cuts first, as before boxes
    double* split[3] = {comm->xsplit, comm->ysplit, comm->zsplit};
    for (int a = 0; a < 3; ++a)
    {
        for (int k = 1; k < grid.n[a]; ++k)
        {
            split[a][k] = (grid.cuts[a][std::size_t(k - 1)] - domain->boxlo[a])/domain->prd[a];
        }
    }
    comm->uniform = 0;   // the ghost and migration searches use the splits
    domain->set_local_box();
    if (moved)
    {
        // atoms may lie any number of boxes away from their new owner; the
        // fixes that move with them (contact history) need their init first
        lmp_->init();
        localAtoms_.clear();
        LAMMPS_NS::Irregular irregular(lmp_);
        irregular.migrate_atoms();
    }
    setup();   // its exchange moves the atoms to their new subdomains
}


// --- restarts ------------------------------------------------------------------
// The step state is a binary file: the tag line, the number of rows and their
// width, then one row of doubles per atom: id, force (3), torque (3), fluid
// force (3) and, with heat transfer, the convective heat flux.

namespace
{

const std::string stepStateTag = "SpoutLab DEM step state 1\n";

} // namespace


int LiggghtsDem::stepStateWidth() const
{
    return hasHeat() ? 11 : 10;
}


std::vector<double> LiggghtsDem::packStepState() const
{
    const auto* atom = lmp_->atom;
    const int width = stepStateWidth();
    std::vector<double> rows(std::size_t(atom->nlocal)*width);
    for (int i = 0; i < atom->nlocal; ++i)
    {
        double* row = &rows[std::size_t(i)*width];
        row[0] = atom->tag[i];
        for (int d = 0; d < 3; ++d)
        {
            row[1 + d] = atom->f[i][d];
            row[4 + d] = atom->torque[i][d];
            row[7 + d] = dragForce_->array_atom[i][d];
        }
        if (hasHeat()) row[10] = convectiveHeatFlux_->vector_atom[i];
    }
    return rows;
}


long LiggghtsDem::unpackStepState(const std::vector<double>& rows)
{
    auto* atom = lmp_->atom;
    const int width = stepStateWidth();
    long found = 0;
    for (std::size_t k = 0; k < rows.size()/width; ++k)
    {
        const double* row = &rows[k*width];
        const int i = atom->map(int(row[0]));
        if (i < 0 || i >= atom->nlocal) continue;
        ++found;
        for (int d = 0; d < 3; ++d)
        {
            atom->f[i][d] = row[1 + d];
            atom->torque[i][d] = row[4 + d];
            dragForce_->array_atom[i][d] = row[7 + d];
        }
        if (hasHeat()) convectiveHeatFlux_->vector_atom[i] = row[10];
    }
    return atom->nlocal - found;
}


std::vector<int> LiggghtsDem::writtenOrder(const std::vector<double>& rows) const
{
    // the local atoms sorted by their row; one without a row goes last
    auto* atom = lmp_->atom;   // its map() is not const
    const int nLocal = atom->nlocal;
    const int width = stepStateWidth();
    std::vector<std::size_t> rowOf(static_cast<std::size_t>(nLocal), rows.size());
    for (std::size_t k = 0; k < rows.size()/width; ++k)
    {
        const int i = atom->map(int(rows[k*width]));
        if (i >= 0 && i < nLocal) rowOf[std::size_t(i)] = k;
    }
    std::vector<int> order(static_cast<std::size_t>(nLocal));
    for (int i = 0; i < nLocal; ++i) order[std::size_t(i)] = i;
    std::stable_sort
    (
        order.begin(), order.end(),
        [&rowOf](int a, int b) { return rowOf[std::size_t(a)] < rowOf[std::size_t(b)]; }
    );
    return order;
}


void LiggghtsDem::restoreOrder(const std::vector<double>& rows)
{
    // A parallel restart reads each atom onto LIGGGHTS' own even split of
    // the box; the set-up on the mesh's boxes (setDecomposition) then moves
    // those on the wrong side of a cut to their rank, at the end of its list
    // (46 of rank 1's 833 on the draft-plate bed's two slabs).  The order
    // is that of every sum over a rank's particles -- their void fraction
    // and Us per cell, the contact forces -- so the restart parted from the
    // uninterrupted run at round-off (one cell's void fraction by 1 ulp at
    // once), which grew to 1e-8 within 6 steps.  The step state's rows are
    // in the order the writing run held its atoms; serially, and whenever
    // no atom moved, that is the order read already.
    const std::vector<int> order = writtenOrder(rows);
    int inOrder = 1;
    for (std::size_t k = 0; k < order.size(); ++k) inOrder = inOrder && order[k] == int(k);
    MPI_Allreduce(MPI_IN_PLACE, &inOrder, 1, MPI_INT, MPI_MIN, comm_);
    if (inOrder) return;
    // LIGGGHTS keeps the contact histories in its neighbour lists, by atom
    // index, between re-neighbourings: into the atoms' own arrays first,
    // as a set-up's first stage does (which then finds nothing newer)
    lmp_->modify->setup_pre_exchange();
    permuteAtoms(order);
    setup();   // ghosts, atom map and neighbour lists of the new order
}


void LiggghtsDem::permuteAtoms(const std::vector<int>& order)
{
    // by cycles, through one spare slot past the local and ghost atoms (a
    // ghost's slot would leave LIGGGHTS' atom map naming an atom there that
    // is not); AtomVec::copy carries the fixes' per-atom data (fluid force,
    // contact history) along
    auto* atom = lmp_->atom;
    const int nLocal = atom->nlocal;
    const int spare = nLocal + atom->nghost;
    if (atom->nmax <= spare) atom->avec->grow(0);
    localAtoms_.clear();
    std::vector<bool> placed(order.size(), false);
    for (int start = 0; start < nLocal; ++start)
    {
        if (placed[std::size_t(start)]) continue;
        placed[std::size_t(start)] = true;
        if (order[std::size_t(start)] == start) continue;
        atom->avec->copy(start, spare, 0);
        int to = start;
        for (int from = order[std::size_t(to)]; from != start; from = order[std::size_t(to)])
        {
            atom->avec->copy(from, to, 0);
            to = from;
            placed[std::size_t(to)] = true;
        }
        atom->avec->copy(spare, to, 0);
    }
}


void LiggghtsDem::writeRestart(const std::string& restartFile, const std::string& stateFile)
{
    Activity doing("writing the restart '" + restartFile + "'");
    command("write_restart " + restartFile);
    const std::vector<double> local = packStepState();
    writeStepState(stateFile, local);
    // The set-up of a restarted run builds new neighbour lists, and LIGGGHTS'
    // contact forces after a rebuild at another step are not quite those of
    // the old lists (measured: the first step after a restart changed the
    // force on 24 of 1500 particles, by up to 4e-4 of it).  Passing through
    // the same set-up here, and restoring the same state, keeps the
    // continuing run on the path a restart from these files takes.
    setup();
    unpackStepState(local);
}


void LiggghtsDem::writeStepState
(
    const std::string& file, const std::vector<double>& local
) const
{
    int rank = 0;
    MPI_Comm_rank(comm_, &rank);
    const std::vector<double> all = gathered(local, comm_, false);
    if (rank != 0) return;

    // a killed run never leaves a truncated state beside a complete restart
    const std::string tmp = file + ".tmp";
    {
        std::ofstream os(tmp, std::ios::binary | std::ios::trunc);
        const std::int64_t rows = std::int64_t(all.size()/stepStateWidth());
        const std::int32_t width = stepStateWidth();
        os.write(stepStateTag.data(), std::streamsize(stepStateTag.size()));
        os.write(reinterpret_cast<const char*>(&rows), sizeof rows);
        os.write(reinterpret_cast<const char*>(&width), sizeof width);
        os.write
        (
            reinterpret_cast<const char*>(all.data()),
            std::streamsize(all.size()*sizeof(double))
        );
        if (!os)
        {
            throw InputError("cannot write the DEM step state '" + tmp + "'");
        }
    }
    std::rename(tmp.c_str(), file.c_str());
}


void LiggghtsDem::readStepState(const std::string& file)
{
    std::ifstream is(file, std::ios::binary);
    std::string tag(stepStateTag.size(), '\0');
    std::int64_t rows = -1;
    std::int32_t width = -1;
    is.read(&tag[0], std::streamsize(tag.size()));
    is.read(reinterpret_cast<char*>(&rows), sizeof rows);
    is.read(reinterpret_cast<char*>(&width), sizeof width);
    if (!is || tag != stepStateTag || width != stepStateWidth() || rows < 0)
    {
        throw InputError
        (
            "DEM step state '" + file + "': expected a '"
          + stepStateTag.substr(0, stepStateTag.size() - 1) + "' file with rows of "
          + std::to_string(stepStateWidth()) + " values (this case's LIGGGHTS input)"
        );
    }
    std::vector<double> all(std::size_t(rows)*width);
    is.read
    (
        reinterpret_cast<char*>(all.data()), std::streamsize(all.size()*sizeof(double))
    );
    if (!is)
    {
        throw InputError("DEM step state '" + file + "': truncated file");
    }
    restoreOrder(all);
    long missing = unpackStepState(all);
    MPI_Allreduce(MPI_IN_PLACE, &missing, 1, MPI_LONG, MPI_SUM, comm_);
    if (missing != 0)
    {
        throw InputError
        (
            "DEM step state '" + file + "': no row for " + std::to_string(missing)
          + " particle(s) of the LIGGGHTS restart beside it"
        );
    }
}

} // namespace spoutlab
