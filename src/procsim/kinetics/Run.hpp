#pragma once
// One run of a case: solve, derive TOC, CO2 and the carbon balance, the time
// to halve TOC and the energetic efficiencies (paper eqs 18-20); write CSV,
// summary and PNG plots.
#include <string>
#include <vector>

#include "kinetics/Case.hpp"
#include "kinetics/Model.hpp"
#include "kinetics/Solvers.hpp"

namespace procsim::kinetics
{

constexpr double carbonMolarMass = 12.011; // g/mol

struct Results
{
    Case cas;
    std::vector<double> t;               // s
    std::vector<Eigen::VectorXd> c;      // all species, mol/L
    std::vector<double> toc;             // mg C/L (organic species only)
    std::vector<double> inorganicCarbon; // mol C in the liquid as CO2 etc.
    std::vector<double> carbonFed;       // mol C fed since t = 0
    std::vector<double> carbonInitial;   // mol C at t = 0 (all species)
    std::vector<double> carbonError;     // |in - out| / in
    long steps = 0;

    double tocNoDischarge(std::size_t i) const; // mg C/L if nothing reacted (initial + fed)
    // interpolated value at time ts of a species (mg/L) or "TOC" (mg C/L)
    double value(const std::string& quantity, double ts) const;
    std::vector<double> series(const std::string& quantity) const; // on t, same units
};

struct Efficiency
{
    bool halfReached = false;
    double tHalf = 0;                                    // s, TOC = 1/2 TOC without discharge
    double jToc = 0;                                     // mol C/J    (eq 18)
    std::vector<std::pair<std::string, double>> jLiquid; // mol/J, eq 19, per initially present species
    std::vector<std::pair<std::string, double>> jGas;    // mol/J, eq 20, per fed species
};

Results runCase(const Case& c);
Results analyse(const Model& model, const Trajectory& tr);
Efficiency efficiency(const Results& r);
double maxCarbonError(const Results& r);

std::string summaryText(const Results& r, const Efficiency& e);
// writes timeseries.csv, summary.txt, summary.csv and (if plots) species.png, toc.png
void writeRun(const Results& r, const Efficiency& e, const std::string& dir, bool plots);

// the case's report times and the end of the run, s
std::vector<double> reportTimes(const Results& r);

// default species to plot: the case's list or every organic species present
std::vector<std::string> plotSpecies(const Results& r);

} // namespace procsim::kinetics
