#pragma once
// The long-time spouted-bed drying predictor (`procsim dryer spouted`).
//
// The CFD-DEM reaches seconds, a batch of corn dries in tens of minutes. The
// predictor carries N sample particles through the circulation the CFD-DEM
// measured (circulation.json: per region a residence-time histogram and the
// time-averaged slip Re, voidage, h, k_m, ...), each standing for N_bed / N
// kernels of the bed, for hours. Every physical law is the physics core's
// (coupling/): the drying model with its per-kernel state (DryingModel), the
// heat-transfer correlation of each region for h and, through its Sherwood
// form, k_m (HeatTransferModel), the moist air (MoistAir, Psychrometrics),
// the corn's heat capacities. Nothing is re-derived here.
//
// Particles. A sample is in one region; when its residence there is over it
// moves to the next region of the cycle (the file's `regions` order) with a
// residence drawn from that region's histogram (a bin with probability
// count/samples, uniform within the bin; with the visits open at the
// window's end, Kaplan-Meier's probabilities and a tail, Residence::censor).
// At t = 0 the samples are placed as
// the stationary circulation has them: region r with probability
// mean_r / sum of means, the time left there the residual of a length-biased
// draw (renewal theory), so the bed starts at its measured holdup. Each
// sample starts at the case's uniform moisture and temperature, or with
// bed.initial_state at those of one kernel of a CFD-DEM particle file
// (sample i the row i mod rows), its region drawn as above. In a
// region over a segment tau (a step cut at residence ends) the kernel is
// advanced exactly as the CFD-DEM's coupling step advances it (the
// singleKernel case's sequence): the drying model's advanceWithLatentHeat at
// the kernel temperature T_p, then
//   q = h A (T_g - T_p),  T_p += tau (q - dW/tau L) / (m_d (c_d + X c_w))
// with X the moisture after the step (explicit in T_p, as LIGGGHTS').
//
// Gas. Its residence is milliseconds against the seconds of the particles'
// changes: a quasi-steady balance of water and energy over a network of
// well-mixed compartments (gasNetwork), one per region and one per core of a
// region (addCore). All the gas crosses the entrainment zone at the base,
// where the jet meets the kernels that enter the spout; then spoutShare of
// the dry air rises through the spout and the rest (downcomerShare) seeps
// through the downcomer, and the two meet again in the fountain region above
// the plates, which all the gas leaves through. Where the statistics measure
// the cores, the zone is the jet, which all the gas crosses first, and the
// rest beside it, which the seepage crosses and exchanges a measured recycle
// with; the fountain region is its core over the spout, which the spout's gas
// enters, and the rest over the downcomers, which the seepage enters, the two
// exchanging the measured flows across the core's sides. The gas the
// particles of a compartment see is the gas leaving it, the gas entering plus
// what its particles gave (water dW, energy sum(dW h_v(T_p)) - q tau) over
// the dry-air flow through it. Explicit like the CFD-DEM's exchange: a
// step's particles see the compartments computed from the step before, a
// compartment fed by one later in the order takes that one's gas of the step
// before; the outlet a step books carries exactly that step's exchange, all
// the compartments' (all their gas leaves through it), so the balances close
// to round-off. With gasModel plugFlow each compartment's gas is a plug flow
// instead, along which it relaxes towards its kernels: they see its mean
// along the compartment, between the entering and the leaving gas (half-way
// where it hardly changes: the jet, the spout). gasModel inlet holds every
// region at the inlet air (unlimited air).
//
// Time step (adaptive): the step is raised (at most x2) or cut (at most /2)
// towards the largest that keeps (1) the largest change of one kernel's
// temperature over one segment below kernelTemperatureChange (the explicit
// heat update and the drying model's held T_p) and (2) the change of the bed-
// mean moisture per step below bedMoistureChange (the gas lags the particles
// by one step), never above maxStep nor half the shortest heating time
// m_d c_d/(h A) of a region (explicit stability). Steps land on output times.
//
// Balances: water, sum of m_d w X over samples lost = integral of G (W_out -
// W_in) dt; energy, the change of the samples' enthalpy m_d w (c_d + X c_w) t
// plus integral G (h_out - h_in) dt plus the heat of sorption sum dW (L -
// h_fg(T_p)) (bound water's, which the kernel enthalpy does not hold) is zero.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "DryingModel.hpp"
#include "HeatTransferModel.hpp"

namespace procsim::dryer::spouted
{

// A residence-time histogram: bin i covers [i w, (i + 1) w).
struct Residence
{
    double binWidth = 0;
    std::vector<double> counts;
    long samples = 0;
    double mean = 0; // as the file gives it [s]
    double std = 0;
    // visits longer than any bin (censor): their share, drawn from an
    // exponential tail past the last bin with mean tailMean [s]
    double tailShare = 0, tailMean = 0;

    double histogramMean() const; // from the bins' midpoints [s]
    // The completed visits (counts) with those still open at the window's
    // end, `censored` (bin i: at least i w so far), as Kaplan-Meier's
    // (actuarial) probability per bin; what lasts beyond the last bin the
    // tail, whose mean puts the whole mean at littleMean (Little's law,
    // holdup / entry rate, which needs no visit to end), or at the window's
    // edge where littleMean falls short of the mean the bins give by less
    // than 3 littleError (its sampling error). counts then hold
    // probabilities and mean is the whole mean. Throws
    // std::invalid_argument when littleMean falls short by more.
    void censor(const std::vector<double>& censored, double littleMean, double littleError);
    // the running sums the draws search (after the counts are set)
    void prepare();
    // a residence from two uniform numbers in [0, 1) (prepared)
    double draw(double u1, double u2) const;
    // the time left of a residence in progress at a random instant
    // (length-biased residence times a uniform fraction), three uniforms
    double drawResidual(double u1, double u2, double u3) const;

    std::vector<double> cumulative, lengthCumulative; // running sums of count_i and count_i (i + 1/2)
};

// One region of the bed as the predictor uses it.
struct Region
{
    std::string name;
    std::string correlation;       // the heat-transfer model's name
    double slipReynolds = 0;       // Re = eps rho |Us - u| d / mu
    double voidage = 1;            // eps
    double h = 0;                  // [W/m2/K] the kernels exchange with: measured or hCorrelation
    double km = 0;                 // [m/s], likewise
    double hCorrelation = 0;       // the region's correlation at its slip Re and voidage
    double kmCorrelation = 0;      // its Sherwood form
    double hFile = 0, kmFile = 0;  // the statistics' measured values (0: none)
    double holdupShare = 0;        // the statistics' holdup / particles (0: none)
    double gasTemperatureFile = 0; // [K] (0: none)
    double gasHumidityFile = -1;   // the statistics' humidity ratio [kg/kg dry air] (-1: none)
    Residence residence;           // empty without circulation
    bool measured = false;         // its conditions from the statistics
    // A gas compartment inside a region of the cycle, its core (the jet
    // inside the entrainment zone, the fountain's core over the spout):
    // partOf its index, share of that region's kernel time spent in it; the
    // region then names it in `core`. -1: none.
    int partOf = -1, core = -1;
    double share = 1;
    // a core: its share of each visit of its region, per visit (a histogram
    // on [0, 1]; empty: every visit spends `share` in it)
    Residence visitFractions;
    // a core: the dry air flowing into it from the rest of its region and out
    // of it into the rest, across its sides, as shares of the inlet's (the
    // statistics' gas.intoJet, gas.intoFountainCore, gas.outOfFountainCore;
    // the jet's outflow to the rest is the seepage plus its inflow)
    double intoCore = 0, outOfCore = 0;
    // the share of that two-way exchange the gas network counts: what
    // carries heat by the statistics' gas.carried (1 without them), the net
    // outOfCore - intoCore kept
    double exchangeShare = 1;
};

// Gas properties as constant/transportProperties has them.
struct GasProperties
{
    double rho, mu, cp, kappa, Dv;
};

struct TimeStepControl
{
    double maxStep = 5;                   // [s]
    double initialStep = 0.1;             // [s]
    double kernelTemperatureChange = 1.0; // [K] per segment
    double bedMoistureChange = 2e-3;      // [kg/kg d.b.] per step
};

struct Case
{
    std::string file;
    std::string statistics;                            // circulation.json ("" without circulation)
    std::string statisticsRun;                         // its run.case
    double cycleMean = 0;                              // its cycle residence mean [s]
    double statisticsInletC = 0, statisticsInletW = 0; // the air of its run
    // operating point
    double inletC = 80, inletW = 0.01, pressure = 101325, ambientC = 20;
    double airFlow = 0;    // dry air [kg/s]
    double fanPower = 0;   // [W]
    double spoutShare = 1; // of the dry air; the rest seeps through entrainment and downcomer
    // the bed
    double bedParticles = 1, diameter = 8e-3, dryMass = 2.5e-4, initialX = 0.3333, initialC = 25;
    double dryHeatCapacity = 1465;
    // bed.initial_state: per-kernel moisture [kg/kg d.b.] and temperature [K]
    // (sample i starts as row i mod rows); empty: initialX, initialC for all
    std::string initialStateFile;
    std::vector<double> initialStateX, initialStateT;
    GasProperties gas{};
    std::shared_ptr<const spoutlab::DryingModel> drying;
    std::string dryingName;
    std::vector<Region>
        regions; // the cycle's order, then its regions' compartments; one region: no circulation
    bool circulating = true;
    bool gasAtInlet = false; // gasModel inlet: unlimited air
    // gasModel plugFlow: each compartment's gas flows through it as a plug,
    // its kernels see the mean along it (Bed::seenShare); compartments: each
    // well mixed, its kernels see the gas leaving it
    bool plugFlow = false;
    // transfer_coefficients measured: each region's h and k_m are the
    // statistics' (the mean over its kernels), not its correlation at the
    // mean slip Re and voidage, which differ where Re and voidage scatter
    bool measuredTransfer = false;
    // the batch
    double targetX = 0.1765; // bed-mean moisture that ends it [kg/kg d.b.]
    bool stopAtTarget = true;
    double limitC = 60;         // kernel-temperature limit
    double duration = 3600;     // longest batch [s]
    double outputInterval = 60; // [s]
    long samples = 10000;
    std::uint64_t seed = 1;
    TimeStepControl step;
};

// The mean over the rest of a region beside its core, from the region's
// mean and the core's, the core holding `share` of the region's kernel time.
double meanBeside(double regionMean, double coreMean, double share);
// A region as two gas compartments, its core and the rest beside it: the
// jet under the spout (region "entrainment", core "jet"), which all the gas
// crosses first, or the fountain's core over the spout (region "fountain",
// core "fountainCore"), which the spout's gas enters. The core holds `share`
// of the region's kernels (`core` the means its kernels saw: slipRe,
// voidage, h, k_m, gas, and its flows intoCore, outOfCore). The region's
// means become the rest's: each is share x the core's + (1 - share) x the
// rest's. Its holdup and gas as the statistics give them stay the region's
// (the predictor reports the region's kernels' gas, time-weighted over
// both). 0 < share < 1; before transferCoefficients.
void addCore(Case& c, const std::string& region, const std::string& name, double share, Region core);

// One inflow of a gas compartment: from the inlet (-1) or the compartment of
// that region index, dry air [kg/s].
struct GasInflow
{
    int from;
    double flow;
};
struct GasCompartment
{
    std::size_t region;
    std::vector<GasInflow> in;
};
// The compartments in the order the gas is solved, and what leaves the bed.
struct GasNetwork
{
    std::vector<GasCompartment> order;
    std::vector<GasInflow> outlet;
};
// The share of a core's measured two-way exchange that carries heat, from
// the temperatures its outflow and inflow carry and those of the core's and
// the rest's gas (Region::exchangeShare).
double exchangeShare(double outT, double inT, double coreT, double restT);
// The case's network: one compartment of the still region, or the four
// regions' and their cores' (the gas paths above). Throws
// std::invalid_argument where a core's flows would leave a compartment more
// gas than enters it.
GasNetwork gasNetwork(const Case& c);

// h and k_m of every region: its correlation's (the physics core's) from
// its slip Re and voidage at the case's gas and kernel diameter, and the
// measured ones instead where the case takes them (measuredTransfer).
void transferCoefficients(Case& c);

struct SeriesPoint
{
    double t;                // [s]
    double xMean, xP5, xP95; // over the samples [kg/kg d.b.]
    double tMeanC, tMaxC;    // kernel temperatures
    double outletC, outletW, outletRH;
    double evaporation; // [kg/s], the bed
    double heaterJ;     // cumulative
    double dt;          // the last step
};

struct Result
{
    std::vector<SeriesPoint> series;
    bool reachedTarget = false;
    double targetTime = 0;           // interpolated in the step that reached it [s]
    double endTime = 0;              // where the run stopped [s]
    double timeAnyAbove = 0;         // time some sample was above the limit [s]
    double meanTimeAbove = 0;        // per kernel [s]
    double highestC = 0;             // hottest kernel temperature seen
    double waterKg = 0;              // evaporated by the bed
    double heaterJ = 0;              // heating the air from ambient, plus the fan
    double dryMassKg = 0;            // of the bed
    double finalX = 0, finalStd = 0; // bed-mean moisture and its spread over kernels
    double waterBalanceRel = 0, energyBalanceRel = 0;
    double sorptionJ = 0; // heat of sorption taken by the bound water
    long steps = 0, segments = 0;
    std::vector<double> holdup;      // time-averaged share of the samples per region
    std::vector<double> gasT, gasW;  // time-averaged gas the samples of each region saw [K], [kg/kg]
    std::vector<double> moisture;    // final X of every sample
    std::vector<double> temperature; // final T_p of every sample [K]
};

// Runs the batch. Deterministic: the same case (seed) gives the same result
// to the bit.
Result run(const Case& c);

} // namespace procsim::dryer::spouted
