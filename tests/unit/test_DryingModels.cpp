// The drying laws of one kernel: their rates by hand from the published
// formulas, their limits (no film, saturated air, X at equilibrium), water
// conserved to round-off, stability from 1e-4 s to a day per step, the wet
// bulb a free-water kernel settles at, and the kernel-diffusion shells against
// Crank's series for a sphere at constant surface moisture.
//
// A kernel of shelled corn: d = 8 mm, dry mass 2.48e-4 kg (1231 kg/m^3 at
// X = 0.33), A = pi d^2 = 2.01062e-4 m^2; air at 60 C, W = 0.01, 1 atm. The
// REA and diffusion parameters below are test values, not a corn fit.

#include "DryingModel.hpp"
#include "InputError.hpp"
#include "KernelDiffusion.hpp"
#include "Psychrometrics.hpp"
#include "ReactionEngineering.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

using namespace spoutlab;

namespace
{

const double pi = std::acos(-1.0);
const double rv = 287.042 / 0.621945; // R_v of the psychrometrics
const double gasConstant = 8.314462618;
const MoistAir air{333.15, 0.01, 101325.0};
const double km = 0.05; // m/s

Kernel kernelAt(double temperature)
{
    return {8e-3, 2.48e-4, temperature};
}

// the hand formulas the models must agree with
double saturated(double temperature)
{
    return psy::saturationPressure(temperature - 273.15) / (rv * temperature);
}
double farVapour(const MoistAir& a)
{
    return a.pressure * a.humidityRatio / (0.621945 + a.humidityRatio) / (rv * a.temperature);
}
double airRh(const MoistAir& a)
{
    return a.pressure * a.humidityRatio / (0.621945 + a.humidityRatio)
           / psy::saturationPressure(a.temperature - 273.15);
}
double hendersonXeq(double rh, double temperature)
{
    return 0.01 * std::pow(-std::log(1.0 - rh) / (8.6541e-5 * (temperature - 273.15 + 49.810)), 1.0 / 1.8634);
}

Parameters reaProps(const std::string& a = "1", const std::string& b = "5", const std::string& c = "1")
{
    Parameters p("constant/couplingProperties/reactionEngineeringProps");
    p.set("a", a).set("b", b).set("c", c);
    return p;
}

Parameters diffusionProps(const std::string& shells = "15", const std::string& kernelSteps = "1")
{
    Parameters p("constant/couplingProperties/kernelDiffusionProps");
    p.set("D0", "5e-6")
        .set("activationEnergy", "30000")
        .set("nShells", shells)
        .set("kernelSteps", kernelSteps);
    return p;
}

std::unique_ptr<DryingModel> make(const std::string& name, const Parameters& props)
{
    return DryingModel::New(name, props);
}

std::string errorOf(const std::string& name, const Parameters& props)
{
    try
    {
        make(name, props);
    }
    catch (const InputError& e)
    {
        return e.what();
    }
    return "";
}

void expectRel(double value, double expected, double tol)
{
    EXPECT_LT(std::fabs(value - expected), tol * std::fabs(expected)) << value << " vs " << expected;
}

} // namespace

// --- selection -----------------------------------------------------------------------

TEST(DryingModels, SelectedByName)
{
    EXPECT_EQ(DryingModel::available(),
              (std::vector<std::string>{"freeWater", "kernelDiffusion", "reactionEngineering"}));
    EXPECT_EQ(make("freeWater", Parameters("x"))->name(), "freeWater");
    EXPECT_EQ(make("reactionEngineering", reaProps())->name(), "reactionEngineering");
    EXPECT_EQ(make("kernelDiffusion", diffusionProps())->name(), "kernelDiffusion");
}

TEST(DryingModels, BadNamesAndMissingParametersNameTheKey)
{
    EXPECT_EQ(errorOf("Lewis", Parameters("constant/couplingProperties/LewisProps")),
              "constant/couplingProperties: key 'dryingModel' expected one of freeWater, kernelDiffusion, "
              "reactionEngineering, got 'Lewis'");
    Parameters noA("constant/couplingProperties/reactionEngineeringProps");
    noA.set("b", "5").set("c", "1");
    EXPECT_EQ(errorOf("reactionEngineering", noA),
              "constant/couplingProperties/reactionEngineeringProps: key 'a' is missing (expected a number)");
    EXPECT_EQ(
        errorOf("reactionEngineering", reaProps("1", "5", "0")),
        "constant/couplingProperties/reactionEngineeringProps: key 'c' expected an exponent > 0, got '0'");
    Parameters noD0("constant/couplingProperties/kernelDiffusionProps");
    noD0.set("activationEnergy", "30000");
    EXPECT_EQ(errorOf("kernelDiffusion", noD0),
              "constant/couplingProperties/kernelDiffusionProps: key 'D0' is missing (expected a number)");
    EXPECT_EQ(errorOf("kernelDiffusion", diffusionProps("1")),
              "constant/couplingProperties/kernelDiffusionProps: key 'nShells' expected a number of shells "
              "from 2 to 200, got '1'");
    EXPECT_EQ(
        errorOf("kernelDiffusion", diffusionProps("15", "0")),
        "constant/couplingProperties/kernelDiffusionProps: key 'kernelSteps' expected a number of coupling "
        "steps from 1 to 1000, got '0'");
    Parameters badIsotherm = diffusionProps();
    badIsotherm.set("isotherm", "GAB");
    EXPECT_EQ(errorOf("kernelDiffusion", badIsotherm),
              "constant/couplingProperties/kernelDiffusionProps: key 'isotherm' expected one of "
              "modifiedChungPfost, modifiedHenderson, got 'GAB'");
}

TEST(DryingModels, AStepOutsideThePreconditionsIsOneLine)
{
    auto model = make("freeWater", Parameters("x"));
    double x = -0.1;
    EXPECT_THROW(model->advance(kernelAt(300.0), x, nullptr, air, km, 1.0), std::domain_error);
    x = 0.2;
    EXPECT_THROW(model->advance(kernelAt(300.0), x, nullptr, air, -km, 1.0), std::domain_error);
    EXPECT_THROW(model->advance(kernelAt(300.0), x, nullptr, air, km, NAN), std::domain_error);
    // a kernel-diffusion state that does not hold the particle's X (another
    // layout: the shells of a state written before it held their modes)
    const KernelDiffusion diffusion(diffusionProps());
    std::vector<double> shells(diffusion.stateSize(), 0.33);
    shells[0] = 0.331;
    try
    {
        diffusion.advance(kernelAt(300.0), x = 0.33, shells.data(), air, km, 1.0);
        ADD_FAILURE() << "no domain_error";
    }
    catch (const std::domain_error& e)
    {
        EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("dryingModel kernelDiffusion: expected a particle state"),
                  std::string::npos)
            << e.what();
    }
}

// --- free water --------------------------------------------------------------------

// m_dot = k_m A (p_ws(T_p)/(R_v T_p) - p_w/(R_v T_g))
TEST(FreeWater, RateByHand)
{
    auto model = make("freeWater", Parameters("x"));
    const double area = pi * 8e-3 * 8e-3;
    for (double tp : {290.0, 305.0, 320.0})
    {
        const double expected = km * area * (saturated(tp) - farVapour(air));
        expectRel(model->rate(kernelAt(tp), 0.3, nullptr, air, km), expected, 1e-12);
    }
    EXPECT_EQ(model->stateSize(), 0);
    EXPECT_EQ(model->rate(kernelAt(305.0), 0.3, nullptr, air, 0.0), 0.0); // no film, no transfer
    EXPECT_EQ(model->rate(kernelAt(305.0), 0.0, nullptr, air, km), 0.0);  // nothing left to evaporate
    // latent heat: free water's, 2501e3 + (1860 - 4186) 31.85 J/kg
    expectRel(model->latentHeat(kernelAt(305.0), 0.3, nullptr), 2501e3 - 2326.0 * 31.85, 1e-12);
}

TEST(FreeWater, AdvanceIsExactConservesAndStopsAtZero)
{
    auto model = make("freeWater", Parameters("x"));
    const Kernel k = kernelAt(305.0);
    const double mdot = model->rate(k, 0.3, nullptr, air, km);
    double x = 0.3;
    const double water = model->advance(k, x, nullptr, air, km, 10.0);
    EXPECT_NEAR(x, 0.3 - mdot * 10.0 / k.dryMass, 1e-15);
    EXPECT_EQ(water, k.dryMass * (0.3 - x));
    // a day: all the water goes, and no more
    x = 0.3;
    EXPECT_EQ(model->advance(k, x, nullptr, air, km, 86400.0), k.dryMass * 0.3);
    EXPECT_EQ(x, 0.0);
    EXPECT_EQ(model->advance(k, x, nullptr, air, km, 60.0), 0.0);
    // a cold kernel in humid air: vapour condenses on it
    const MoistAir humid{333.15, 0.1, 101325.0};
    x = 0.3;
    const double condensed = model->advance(kernelAt(290.0), x, nullptr, humid, km, 1.0);
    EXPECT_LT(condensed, 0.0);
    EXPECT_GT(x, 0.3);
}

// A kernel with plenty of water whose temperature follows its heat balance,
//   m c dT_p/dt = h A (T_g - T_p) - m_dot h_fg(T_p),
// settles where the two terms balance: the wet bulb of the gas-film laws,
// solved here by bisection. With k_m rho c_p = h (Lewis number 1, rho and c_p
// of the moist air) it lies 1.1 K below the psychrometric wet bulb at
// 60 C / W = 0.01 (27.65 C): the film law drives with vapour densities at T_p
// and T_g, adiabatic saturation with humidity ratios, and the dry air is
// denser at the cold surface.
TEST(FreeWater, SettlesAtTheWetBulb)
{
    auto model = make("freeWater", Parameters("x"));
    const double h = 50.0, area = pi * 8e-3 * 8e-3;
    const double rho = psy::density(60.0, air.humidityRatio, air.pressure);
    const double cp = (1006.0 + 1860.0 * air.humidityRatio) / (1.0 + air.humidityRatio);
    const double kmLewis = h / (rho * cp);
    auto balance = [&](double tp) {
        return h * (air.temperature - tp)
               - kmLewis * psy::latentHeat(tp - 273.15) * (saturated(tp) - farVapour(air));
    };
    double lo = 273.2, hi = air.temperature;
    for (int i = 0; i < 100; ++i) (balance(0.5 * (lo + hi)) > 0.0 ? lo : hi) = 0.5 * (lo + hi);
    const double wetBulb = 0.5 * (lo + hi);

    Kernel k = kernelAt(300.0);
    double x = 10.0; // never runs dry here
    const double dt = 0.5;
    for (int step = 0; step < 4000; ++step) // 2000 s, about 30 thermal time constants
    {
        const double evaporated = model->advance(k, x, nullptr, air, kmLewis, dt);
        const double heat =
            h * area * (air.temperature - k.temperature) * dt - evaporated * model->latentHeat(k, x, nullptr);
        k.temperature += heat / (k.dryMass * (1465.0 + x * 4186.0));
    }
    EXPECT_NEAR(k.temperature, wetBulb, 0.01);
    const double psychrometric = psy::wetBulb(60.0, air.humidityRatio, air.pressure) + 273.15;
    EXPECT_NEAR(psychrometric, 273.15 + 27.65, 0.01);
    EXPECT_NEAR(k.temperature - psychrometric, -1.12, 0.05);
}

// --- reaction engineering approach ---------------------------------------------------

// rho_v,s = exp(-f dE_v,inf/(R T_p)) rho_v,sat(T_p), dE_v,inf = -R T_g ln RH,
// f = a exp(-b (X - X_eq)^c), X_eq of the modified Henderson at (RH, T_g).
TEST(ReactionEngineering, RateByHand)
{
    auto model = make("reactionEngineering", reaProps("0.98", "5", "0.8"));
    const double rh = airRh(air), xeq = hendersonXeq(rh, air.temperature);
    const double area = pi * 8e-3 * 8e-3;
    for (double x : {0.05, 0.15, 0.33})
    {
        const double tp = 320.0;
        const double f = 0.98 * std::exp(-5.0 * std::pow(std::max(0.0, x - xeq), 0.8));
        const double dEinf = -gasConstant * air.temperature * std::log(rh);
        const double surface = std::exp(-f * dEinf / (gasConstant * tp)) * saturated(tp);
        const double expected = km * area * (surface - farVapour(air));
        expectRel(model->rate(kernelAt(tp), x, nullptr, air, km), expected, 1e-10);
    }
}

TEST(ReactionEngineering, NothingMovesAtEquilibriumAndEverythingTowardsIt)
{
    auto model = make("reactionEngineering", reaProps());
    const Kernel k = kernelAt(air.temperature);
    const double xeq = hendersonXeq(airRh(air), air.temperature);
    const double free = km * pi * 64e-6 * (saturated(k.temperature) - farVapour(air));
    EXPECT_LT(std::fabs(model->rate(k, xeq, nullptr, air, km)), 1e-12 * free);
    EXPECT_GT(model->rate(k, xeq + 0.1, nullptr, air, km), 0.0);
    // below X_eq f = a (the relative activation energy's value at X_eq): a
    // kernel at the air's temperature neither dries nor takes water up
    EXPECT_LT(std::fabs(model->rate(k, 0.5 * xeq, nullptr, air, km)), 1e-12 * free);
    // long steps approach the equilibrium and never cross it
    double x = 0.33;
    for (int i = 0; i < 500; ++i)
    {
        model->advance(k, x, nullptr, air, km, 600.0);
        EXPECT_GE(x, xeq * (1.0 - 1e-12)); // (X_eq by hand, to round-off)
    }
    EXPECT_NEAR(x, xeq, 1e-6);
    x = 0.33;
    model->advance(k, x, nullptr, air, km, 1e9);
    EXPECT_GE(x, xeq * (1.0 - 1e-12));
    EXPECT_NEAR(x, xeq, 1e-6);
}

// Saturated air: dE_v,inf -> 0, the surface is saturated, the REA dries as free water.
TEST(ReactionEngineering, NearlySaturatedAirGivesFreeWater)
{
    const double wNearSat = psy::humidityRatioFromRH(60.0, 0.99999, 101325.0);
    const MoistAir wet{333.15, wNearSat, 101325.0};
    auto rea = make("reactionEngineering", reaProps());
    auto free = make("freeWater", Parameters("x"));
    const Kernel k = kernelAt(350.0); // hot kernel in saturated air: it still dries
    expectRel(rea->rate(k, 0.2, nullptr, wet, km), free->rate(k, 0.2, nullptr, wet, km), 1e-4);
}

TEST(ReactionEngineering, ConservesAndIsStableFromATenthOfAMillisecondToADay)
{
    auto model = make("reactionEngineering", reaProps());
    const Kernel k = kernelAt(330.0);
    double previous = 0.33;
    for (double dt : {1e-4, 1e-2, 1.0, 60.0, 3600.0, 86400.0})
    {
        double x = 0.33;
        const double rate = model->rate(k, x, nullptr, air, km);
        const double water = model->advance(k, x, nullptr, air, km, dt);
        EXPECT_EQ(water, k.dryMass * (0.33 - x));
        EXPECT_TRUE(std::isfinite(x));
        EXPECT_LE(x, previous);                            // a longer step dries further ...
        EXPECT_GE(x, 0.0);                                 // ... but never below zero
        if (dt == 1e-4) expectRel(water, rate * dt, 1e-6); // a short step: the rate times dt
        previous = x;
    }
    // zero film: nothing moves
    double x = 0.33;
    EXPECT_EQ(model->advance(k, x, nullptr, air, 0.0, 60.0), 0.0);
    EXPECT_EQ(x, 0.33);
    // ten minutes in one step against 6000 steps of 0.1 s: within 1 % of the change
    double fine = 0.33, coarse = 0.33;
    for (int i = 0; i < 6000; ++i) model->advance(k, fine, nullptr, air, km, 0.1);
    model->advance(k, coarse, nullptr, air, km, 600.0);
    EXPECT_NEAR(coarse, fine, 0.01 * (0.33 - fine));
}

// --- kernel diffusion -----------------------------------------------------------------

TEST(KernelDiffusion, DiffusivityAndState)
{
    const KernelDiffusion model(diffusionProps());
    // 5e-6 exp(-30000/(8.314462618 333.15)) = 9.89367e-11 m^2/s
    expectRel(model.diffusivity(333.15), 9.89367e-11, 1e-5);
    EXPECT_EQ(model.shells(), 15);
    EXPECT_EQ(model.stateSize(), 16);
    double sum = 0.0;
    for (int i = 0; i < model.shells(); ++i) sum += model.weight(i);
    EXPECT_NEAR(sum, 1.0, 1e-15);
    std::vector<double> state(model.stateSize()), shells(model.shells());
    model.initialise(0.33, state.data());
    model.shellMoistures(state.data(), shells.data());
    for (double v : shells) EXPECT_EQ(v, 0.33);
    EXPECT_EQ(state[model.shells()], 0.33); // X_s
}

// The shells' equations decouple in modes v_k (K v = lambda W v), what the
// model steps: W-orthonormal, the uniform one at lambda = 0, and the slowest
// others near the diffusion modes of a sphere with a closed surface,
// lambda = mu^2, tan mu = mu: 4.4934^2 = 20.191 and 7.7253^2 = 59.680
// (Carslaw and Jaeger 1959, sec. 9.4; here with the surface flux through
// the outer half-shell left out, the discretisation's error is a few %).
TEST(KernelDiffusion, ShellModesAreThoseOfASphere)
{
    const KernelDiffusion model(diffusionProps());
    const int n = model.shells();
    std::vector<std::vector<double>> v(n, std::vector<double>(n));
    std::vector<double> unit(model.stateSize(), 0.0);
    for (int k = 0; k < n; ++k)
    {
        std::fill(unit.begin(), unit.end(), 0.0);
        unit[k] = 1.0;
        model.shellMoistures(unit.data(), v[k].data());
    }
    for (int k = 0; k < n; ++k)
    {
        for (int l = 0; l < n; ++l)
        {
            double product = 0.0;
            for (int i = 0; i < n; ++i) product += model.weight(i) * v[k][i] * v[l][i];
            EXPECT_NEAR(product, k == l ? 1.0 : 0.0, 1e-12) << k << " " << l;
        }
        if (k > 0)
        {
            EXPECT_GT(model.decayRate(k), model.decayRate(k - 1));
        }
    }
    for (int i = 0; i < n; ++i) EXPECT_EQ(v[0][i], 1.0);
    EXPECT_EQ(model.decayRate(0), 0.0);
    expectRel(model.decayRate(1), 20.191, 0.03);
    expectRel(model.decayRate(2), 59.680, 0.05);
}

// Crank (The mathematics of diffusion, 1975, eq 6.20): a sphere of radius R
// at uniform X_0 whose surface is held at X_eq from t = 0 has the mean
//   MR = (X - X_eq)/(X_0 - X_eq) = 6/pi^2 sum_n n^-2 exp(-n^2 pi^2 D t/R^2).
// A film far faster than the diffusion holds the surface at X_eq (k_m =
// 1000 m/s: the film conductance exceeds the kernel's by 1e5). With the
// default 15 shells the mean X and MR are within 0.5 % until MR = 0.1, the
// steps growing from 1 ms to a minute (the model cuts them to D dt/R^2 <= 5e-5).
TEST(KernelDiffusion, MatchesCranksSeriesAtConstantSurfaceMoisture)
{
    const KernelDiffusion model(diffusionProps());
    const Kernel k = kernelAt(air.temperature);
    const double xeq = hendersonXeq(airRh(air), air.temperature), x0 = 0.33;
    const double tauPerSecond = model.diffusivity(k.temperature) / (4e-3 * 4e-3);
    auto crank = [&](double tau) {
        const int terms = static_cast<int>(std::sqrt(60.0 / (pi * pi * tau))) + 2;
        double sum = 0.0;
        for (int n = terms; n >= 1; --n) sum += std::exp(-n * n * pi * pi * tau) / (n * n);
        return 6.0 / (pi * pi) * sum;
    };
    std::vector<double> state(model.stateSize());
    model.initialise(x0, state.data());
    double x = x0, t = 0.0, dt = 1e-3, worstMr = 0.0, worstX = 0.0;
    int steps = 0;
    for (; steps < 100000; ++steps)
    {
        model.advance(k, x, state.data(), air, 1000.0, dt);
        t += dt;
        dt = std::min(60.0, 1.05 * dt);
        const double exact = crank(tauPerSecond * t);
        if (exact < 0.1) break;
        const double mr = (x - xeq) / (x0 - xeq);
        worstMr = std::max(worstMr, std::fabs(mr / exact - 1.0));
        const double xExact = xeq + exact * (x0 - xeq);
        worstX = std::max(worstX, std::fabs(x / xExact - 1.0));
    }
    EXPECT_LT(worstMr, 0.005);
    EXPECT_LT(worstX, 0.005);
    EXPECT_GT(steps, 100);
    EXPECT_NEAR(state[model.shells()], xeq, 1e-4 * xeq); // the surface sat at X_eq
}

TEST(KernelDiffusion, ConservesWaterToRoundOff)
{
    const KernelDiffusion model(diffusionProps());
    const Kernel k = kernelAt(320.0);
    std::vector<double> state(model.stateSize());
    model.initialise(0.33, state.data());
    double x = 0.33;
    std::vector<double> before(model.shells()), after(model.shells());
    for (double dt : {1e-4, 0.01, 1.0, 60.0, 600.0})
    {
        model.shellMoistures(state.data(), before.data());
        const double xBefore = x;
        const double rate = model.rate(k, x, state.data(), air, km);
        const double water = model.advance(k, x, state.data(), air, km, dt);
        model.shellMoistures(state.data(), after.data());
        double shellWater = 0.0, mean = 0.0;
        for (int i = 0; i < model.shells(); ++i)
        {
            shellWater += k.dryMass * model.weight(i) * (before[i] - after[i]);
            mean += model.weight(i) * after[i];
        }
        EXPECT_EQ(water, k.dryMass * (xBefore - x));
        EXPECT_NEAR(water, shellWater, 1e-15 * k.dryMass);
        EXPECT_NEAR(x, mean, 1e-15);
        if (dt == 1e-4) expectRel(water, rate * dt, 1e-4);
    }
}

TEST(KernelDiffusion, StableAndBoundedFromATenthOfAMillisecondToADay)
{
    const KernelDiffusion model(diffusionProps());
    const Kernel k = kernelAt(350.0);
    for (double dt : {1e-4, 0.02, 1.0, 60.0, 3600.0, 86400.0})
    {
        std::vector<double> state(model.stateSize());
        model.initialise(0.33, state.data());
        double x = 0.33;
        for (int i = 0; i < 20; ++i)
        {
            const double previous = x;
            model.advance(k, x, state.data(), air, km, dt);
            EXPECT_LE(x, previous) << dt;
        }
        const double surface = state[model.shells()];
        std::vector<double> shell(model.shells());
        model.shellMoistures(state.data(), shell.data());
        for (int i = 0; i < model.shells(); ++i)
        {
            EXPECT_TRUE(std::isfinite(shell[i]));
            EXPECT_GE(shell[i], surface - 1e-12) << dt << " shell " << i; // the surface is the driest
            EXPECT_LE(shell[i], 0.33 + 1e-12) << dt;
            if (i > 0)
            {
                EXPECT_LE(shell[i], shell[i - 1] + 1e-12); // drier outwards
            }
        }
    }
}

TEST(KernelDiffusion, TheFilmLimitsTheSurface)
{
    const KernelDiffusion model(diffusionProps());
    const Kernel k = kernelAt(air.temperature);
    const double xeq = hendersonXeq(airRh(air), air.temperature);
    std::vector<double> state(model.stateSize());
    // no film: nothing leaves, nothing moves
    model.initialise(0.33, state.data());
    double x = 0.33;
    EXPECT_EQ(model.rate(k, x, state.data(), air, 0.0), 0.0);
    EXPECT_NEAR(model.advance(k, x, state.data(), air, 0.0, 600.0), 0.0, 1e-15 * k.dryMass);
    std::vector<double> shell(model.shells());
    model.shellMoistures(state.data(), shell.data());
    for (int i = 0; i < model.shells(); ++i) EXPECT_NEAR(shell[i], 0.33, 1e-14);
    // a real film: the surface between X_eq and the outer shell, in equilibrium
    // with the vapour the film carries: k_m A (a_w(X_s) rho_sat - rho_inf) = m_dot
    model.initialise(0.33, state.data());
    x = 0.33;
    model.advance(k, x, state.data(), air, km, 60.0);
    const double surface = state[model.shells()];
    model.shellMoistures(state.data(), shell.data());
    EXPECT_GT(surface, xeq);
    EXPECT_LT(surface, shell[model.shells() - 1]);
    const double aw = 1.0 - std::exp(-8.6541e-5 * (60.0 + 49.810) * std::pow(100.0 * surface, 1.8634));
    const double film = km * pi * 64e-6 * (aw * saturated(k.temperature) - farVapour(air));
    expectRel(model.rate(k, x, state.data(), air, km), film, 1e-3);
    // the heat taken is the grain's at the surface moisture
    EXPECT_EQ(
        model.latentHeat(k, x, state.data()),
        SorptionIsotherm::New("modifiedHenderson", Parameters("x"))->latentHeat(surface, k.temperature));
}

// What a coupling step of the spouted bed asks of each kernel (3e-4 s steps,
// a hot kernel in a strong film): the water a backward-Euler step loses is
// the film's flux at the step's new surface, dt k_m A (a_w(X_s) rho_sat -
// rho_inf), by the hand formulas, to the round-off of m_d (X_old - X_new) (a
// few ulps of X against a step's change of 1e-6 X); and the latent heat and the
// step in one call are the two calls' to the last bit, for every model.
TEST(KernelDiffusion, EachStepLosesWhatTheFilmCarriesAtItsSurface)
{
    const KernelDiffusion model(diffusionProps());
    const MoistAir hot{420.0, 0.012, 101325.0};
    const Kernel k = kernelAt(360.0);
    std::vector<double> state(model.stateSize());
    model.initialise(0.33, state.data());
    double x = 0.33, worst = 0.0;
    for (int i = 0; i < 2000; ++i)
    {
        const double roundOff = 16.0 * 2.2e-16 * x * k.dryMass;
        const double water = model.advance(k, x, state.data(), hot, 0.08, 3e-4);
        const double surface = state[model.shells()];
        const double aw =
            1.0 - std::exp(-8.6541e-5 * (360.0 - 273.15 + 49.810) * std::pow(100.0 * surface, 1.8634));
        const double film = 3e-4 * 0.08 * pi * 64e-6 * (aw * saturated(k.temperature) - farVapour(hot));
        worst = std::max(worst, std::fabs(water - film) / (roundOff + 1e-13 * film));
    }
    EXPECT_LT(worst, 1.0);
    EXPECT_LT(x, 0.33);
}

TEST(DryingModels, LatentHeatAndAdvanceInOneCallAreTheTwoCalls)
{
    const MoistAir hot{420.0, 0.012, 101325.0};
    for (const char* name : {"freeWater", "reactionEngineering", "kernelDiffusion", "kernelDiffusion 5"})
    {
        const std::string model = std::string(name).substr(0, std::string(name).find(' '));
        auto m = make(model, model != "kernelDiffusion" ? reaProps()
                             : name == model            ? diffusionProps()
                                                        : diffusionProps("15", "5"));
        std::vector<double> one(m->stateSize() + 1), two(one);
        m->initialise(0.33, one.data());
        m->initialise(0.33, two.data());
        double x1 = 0.33, x2 = 0.33;
        for (double dt : {3e-4, 3e-4, 0.01, 1.0, 600.0, 3e-4})
        {
            const Kernel k = kernelAt(dt < 1e-3 ? 330.0 : 340.0);
            const double heat1 = m->latentHeat(k, x1, one.data());
            const double water1 = m->advance(k, x1, one.data(), hot, 0.08, dt);
            double heat2 = 0.0;
            const double water2 = m->advanceWithLatentHeat(k, x2, two.data(), hot, 0.08, dt, heat2);
            EXPECT_EQ(heat1, heat2) << name << " " << dt;
            EXPECT_EQ(water1, water2) << name << " " << dt;
            EXPECT_EQ(x1, x2) << name << " " << dt;
            EXPECT_EQ(one, two) << name << " " << dt;
        }
    }
}

// kernelSteps M: the kernel advanced once per M coupling steps over M dt (the
// gas, k_m and T_p of the block's first step), its water released in M equal
// shares. A particle of the spouted bed, 3e-4 s steps, crossing between spout
// (hot fast gas) and downcomer (cooler, slower) every 0.1 s with its own
// temperature following, for 20 s: against the resolved kernel (M = 1) the
// water lost differs by far less than the 0.5 % the shells are verified to
// (Crank), though a block holds the surroundings for 3 ms of each 100 ms leg:
// at the blocks' ends within 1e-3 from the fifth cycle (1 s) on, 2.5e-4 at 20
// s, and so the latent heat taken.
TEST(KernelDiffusion, KernelStepsFollowTheResolvedKernelAcrossSpoutAndDowncomer)
{
    const KernelDiffusion resolved(diffusionProps()), blocks(diffusionProps("15", "10"));
    EXPECT_EQ(blocks.kernelSteps(), 10);
    EXPECT_EQ(blocks.stateSize(), resolved.stateSize() + 2);
    std::vector<double> one(resolved.stateSize()), ten(blocks.stateSize());
    resolved.initialise(0.33, one.data());
    blocks.initialise(0.33, ten.data());
    double x1 = 0.33, x10 = 0.33, water1 = 0.0, water10 = 0.0, heat1 = 0.0, heat10 = 0.0, worst = 0.0;
    const double dt = 3e-4;
    for (int i = 0; i < 66667; ++i)
    {
        const double t = i * dt, phase = std::fmod(t, 0.2);
        const bool spout = phase < 0.1;
        const MoistAir gas{spout ? 420.0 : 345.0, spout ? 0.008 : 0.014, 101325.0};
        const double temperature = spout ? 330.0 + 200.0 * phase : 350.0 - 150.0 * (phase - 0.1);
        const Kernel k = kernelAt(temperature);
        double l1 = 0.0, l10 = 0.0;
        const double w1 = resolved.advanceWithLatentHeat(k, x1, one.data(), gas, spout ? 0.09 : 0.02, dt, l1);
        const double w10 =
            blocks.advanceWithLatentHeat(k, x10, ten.data(), gas, spout ? 0.09 : 0.02, dt, l10);
        water1 += w1;
        water10 += w10;
        heat1 += w1 * l1;
        heat10 += w10 * l10;
        // at the end of each block X is the kernel's mean again (between, the
        // block's water is still being released: up to half a block behind)
        if (i % 10 == 9 && t > 1.0) worst = std::max(worst, std::fabs(water10 / water1 - 1.0));
    }
    std::printf("water %.6e vs %.6e, worst relative %.3e, heat %.3e\n", water1, water10, worst,
                heat10 / heat1 - 1);
    EXPECT_GT(water1, 1e-3 * kernelAt(300.0).dryMass);
    EXPECT_LT(worst, 1e-3);
    EXPECT_LT(std::fabs(heat10 / heat1 - 1.0), 1e-3);
}

// Conservative step by step and over a block: each share is m_d (X_old -
// X_new), a block's shares add up to what the kernel lost, X ends the block
// on the mean of the shells; and the state is all there is (a copy of it
// mid-block, as a restart holds it, continues the same to the bit).
TEST(KernelDiffusion, KernelStepsConserveAndRestartFromTheirState)
{
    const KernelDiffusion blocks(diffusionProps("15", "7"));
    const Kernel k = kernelAt(350.0);
    std::vector<double> state(blocks.stateSize()), shells(blocks.shells());
    blocks.initialise(0.33, state.data());
    double x = 0.33;
    for (int block = 0; block < 3; ++block)
    {
        const double start = x;
        double water = 0.0;
        for (int i = 0; i < 7; ++i)
        {
            const double before = x;
            const double w = blocks.advance(k, x, state.data(), air, km, 3e-4);
            EXPECT_EQ(w, k.dryMass * (before - x));
            EXPECT_LT(x, before);
            water += w;
        }
        blocks.shellMoistures(state.data(), shells.data());
        double mean = 0.0;
        for (int i = 0; i < blocks.shells(); ++i) mean += blocks.weight(i) * shells[i];
        EXPECT_EQ(x, blocks.meanMoisture(state.data()));
        EXPECT_NEAR(x, mean, 1e-15);
        EXPECT_NEAR(water, k.dryMass * (start - x), 1e-16 * k.dryMass);
    }
    for (int i = 0; i < 3; ++i) blocks.advance(k, x, state.data(), air, km, 3e-4); // mid-block
    const KernelDiffusion restarted(diffusionProps("15", "7"));
    std::vector<double> copy(state);
    double y = x;
    for (int i = 0; i < 20; ++i)
    {
        double l1 = 0.0, l2 = 0.0;
        const double w1 = blocks.advanceWithLatentHeat(k, x, state.data(), air, km, 3e-4, l1);
        const double w2 = restarted.advanceWithLatentHeat(k, y, copy.data(), air, km, 3e-4, l2);
        EXPECT_EQ(w1, w2);
        EXPECT_EQ(l1, l2);
        EXPECT_EQ(x, y);
    }
    EXPECT_EQ(state, copy);
}

// Inside a block the step needs no gas (needsGas), and release() takes it
// without: the same water, moisture, state and latent heat as the step given
// the gas, to the bit; at a block's start (the gas needed) and for a model
// whose every step needs the gas it refuses.
TEST(KernelDiffusion, ReleaseIsTheStepInsideABlockWithoutTheGas)
{
    const KernelDiffusion blocks(diffusionProps("15", "4"));
    const Kernel k = kernelAt(350.0);
    std::vector<double> state(blocks.stateSize()), copy(state);
    blocks.initialise(0.33, state.data());
    double x = 0.33;
    int released = 0;
    for (int i = 0; i < 12; ++i)
    {
        if (blocks.needsGas(state.data()))
        {
            double latent = 0.0, y = x;
            copy = state;
            EXPECT_THROW(blocks.release(k.dryMass, y, copy.data(), latent), std::domain_error);
            blocks.advance(k, x, state.data(), air, km, 3e-4);
            continue;
        }
        copy = state;
        double y = x, l1 = 0.0, l2 = 0.0;
        const double w1 = blocks.advanceWithLatentHeat(k, x, state.data(), air, km, 3e-4, l1);
        const double w2 = blocks.release(k.dryMass, y, copy.data(), l2);
        EXPECT_EQ(w1, w2) << i;
        EXPECT_EQ(l1, l2) << i;
        EXPECT_EQ(x, y) << i;
        EXPECT_EQ(state, copy) << i;
        ++released;
    }
    EXPECT_EQ(released, 9);
    auto free = make("freeWater", reaProps());
    double latent = 0.0, y = 0.3;
    EXPECT_THROW(free->release(k.dryMass, y, nullptr, latent), std::logic_error);
    const KernelDiffusion resolved(diffusionProps());
    std::vector<double> row(resolved.stateSize());
    resolved.initialise(0.33, row.data());
    EXPECT_THROW(resolved.release(k.dryMass, y, row.data(), latent), std::logic_error);
}
