#pragma once
// Physical model of a batch hot-air tray dryer with recirculation and
// partial venting (see README.md in this directory for the equations).
//
// Air loop (per unit time, dry-air flows in kg/s):
//   return chamber (well mixed, holdup M_a) --(G - G_v)--> fans + heaters <-- G_v ambient make-up
//   heaters: mixed air heated to the hot-air set-point (power capped)
//   short-circuit: a share s of the make-up air is heated and leaves through
//             the vents without reaching the trays (old ducts);
//   supply G - s*G_v (recirculated + the rest of the make-up air) passes over
//             the trays into the return chamber
//   return chamber: (1 - s)*G_v humid air leaves through the vents, G - G_v recirculates
// Return air above saturation condenses on the walls and drains.
// Trays: cart c, tray k; air share phi_ck (mean 1) from the distribution
// field, heat-transfer coefficient h*phi_ck^n_u.  Product per tray: water
// mass and enthalpy.  Gas-film evaporation capacity m_ext = h A / c_humid x
// 0.622 (p_ws(T_product) - p_w) / (p - p_w) (Lewis analogy).  Drying, one of:
//  thin layer (default): internal rate m_int = m_dry k(T_p) (X - X_eq),
//    k = k_ref exp(-Ea/R (1/T_p - 1/T_ref)), in series with the gas film:
//    m = m_int m_ext / (m_int + m_ext);
//  characteristic curve: m = m_ext f, f = 1 above X_cr and
//    ((X - X_eq)/(X_cr - X_eq))^n below.  The
// equilibrium moisture X_eq follows the air's relative humidity through the
// Oswin isotherm X_eq = A (a/(1-a))^B, so humid (badly vented) air slows the
// end of drying.
#include <string>
#include <vector>

namespace procsim::dryer
{

struct DryerCase
{
    std::string name;
    // layout
    int carts = 9;
    int traysPerCart = 15;
    int piecesPerTray = 160;
    double pieceDiameter = 0.0095; // m
    double pieceLength = 0.9;      // m (pieces laid across the 0.9 m tray)
    // product
    double dryMass = 1000; // kg bone-dry, whole batch
    double x0 = 0.5;       // initial average moisture, dry basis
    double xTarget = 0.12; // batch average at which drying stops
    double x0Spread = 0.0; // relative std dev of initial tray moisture
    unsigned seed = 1;     // for the initial-moisture pattern
    double cpDry = 1500;   // J/(kg K) bone-dry product
    double scorchC = 75;   // product temperature that scorches
    // kinetics
    enum class Kinetics
    {
        ThinLayer,           // internal (Lewis/Arrhenius) and gas-film resistances in series
        CharacteristicCurve, // gas-film rate x f(X) (constant + falling rate)
    };
    Kinetics kinetics = Kinetics::ThinLayer;
    double rateConstant = 0.2 / 3600; // 1/s at the reference temperature (thin layer)
    double referenceC = 70;           // degC
    double activationEnergy = 20e3;   // J/mol
    double xCritical = 0.6;
    double oswinA = 0.1; // Oswin isotherm, kg/kg dry basis
    double oswinB = 0.35;
    double fallingExponent = 1.0;
    double hConv = 15;             // W/(m2 K) at the mean air share
    double velocityExponent = 0.8; // h ~ u^n_u
    // air loop
    double hotAirC = 70;
    double ambientC = 28.6;
    double ambientRH = 0.75;
    double pressure = 101325;
    double circulation = 10;       // G, kg dry air / s through fans
    double ventedFraction = 0.03;  // G_v / G
    double ventShortCircuit = 0.0; // s: share of make-up air vented without reaching the trays
    double heaterPower = 90e3;     // W, maximum
    double fanPower = 5e3;         // W, all fans
    double wallUA = 200;           // W/K, walls + roof + doors
    double airHoldup = 100;        // kg dry air inside the dryer
    // air distribution (relative air shares; normalised to mean 1)
    std::vector<double> cartFactors; // size carts (empty = uniform)
    std::vector<double> trayFactors; // size traysPerCart (empty = uniform)
    // run control
    double maxTime = 30 * 3600.0; // s
    double outputInterval = 600;  // s
    double relTol = 1e-7;

    int trays() const { return carts * traysPerCart; }
    double areaPerTray() const;            // m2 exposed product surface
    std::vector<double> airShares() const; // phi_ck, mean 1
    std::vector<double> initialTrayMoisture() const;
    double equilibriumMoisture(double relativeHumidity) const;
};

struct TimePoint
{
    double t;        // s
    double tSupply;  // degC
    double tReturn;  // degC
    double wSupply;  // kg/kg
    double wReturn;  // kg/kg
    double rhReturn; // 0..1
    double xAvg, xMin, xMax;
    double tProductMax;  // degC
    double tProductMean; // degC
    double heaterW;
    double evaporationKgPerS;
    double electricityJ; // cumulative heaters + fans
};

struct BatchResult
{
    bool reachedTarget = false;
    double dryingTime = 0;   // s (to target, or maxTime)
    double electricityJ = 0; // heaters + fans up to dryingTime
    double heaterJ = 0, fanJ = 0, wallLossJ = 0, ventNetJ = 0;
    double waterEvaporated = 0; // kg (product water lost)
    double condensateKg = 0;    // kg condensed on the walls (supersaturated return air)
    double specificEnergy = 0;  // J/kg
    double eta = 0;             // with the given latent heat per kg
    double latentPerKg = 0;
    double tProductMax = 0; // degC, highest tray temperature in the batch
    bool scorched = false;
    double f1 = 0, f2 = 0;       // % of trays deviating 5-10 % and > 10 % from the mean
    double waterBalanceRel = 0;  // |residual| / initial product water
    double energyBalanceRel = 0; // |residual| / heater+fan energy
    std::vector<TimePoint> series;
    std::vector<double> trayX0, trayX, trayT;     // per tray, cart-major
    std::vector<std::vector<double>> trayXSeries; // per output time, per tray
};

// Runs one batch.  The latent heat per kg for eta uses the convention
// "liquid at ambient -> vapour at the hot-air temperature" unless
// latentPerKg > 0 is given.
BatchResult simulate(const DryerCase& c, double latentPerKg = 0.0);

// Non-uniformity: percentages of trays whose |X - mean| / mean is in
// [5, 10] % (f1) and above 10 % (f2).
void nonUniformity(const std::vector<double>& x, double& f1, double& f2);

} // namespace procsim::dryer
