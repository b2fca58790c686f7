// The three integrators against analytic solutions, each other, a published
// stiff reference solution, and the carbon balance.
#include <gtest/gtest.h>

#include <cmath>

#include "TestUtil.hpp"
#include "kinetics/Run.hpp"
#include "kinetics/Solvers.hpp"

using namespace procsim::kinetics;

namespace
{

// A + OH -> B (k = 2e9 L/mol/s), B + OH -> 2 CO2... with constant [OH] and a feed of A
const char* chainMechanism = R"(
name: chain
radical: OH
species:
  - {name: A, molar_mass_g_per_mol: 44.0, carbon: 2}
  - {name: B, molar_mass_g_per_mol: 60.0, carbon: 2}
  - {name: OH, molar_mass_g_per_mol: 17.0, carbon: 0}
  - {name: CO2, molar_mass_g_per_mol: 44.0, carbon: 1, organic: false}
reactions:
  - {id: ka, equation: "A + OH -> B", k: 2.0e9, units: L/mol/s}
  - {id: kb, equation: "B + OH -> 2 CO2", k: 0.5e9, units: L/mol/s}
)";

std::string chainCase(const std::string& method, double feedPpm)
{
    kt::writeFile("chain_mech.yaml", chainMechanism);
    return kt::writeFile("chain_" + method + ".yaml", R"(
mechanism: chain_mech.yaml
reactor: {liquid_volume_L: 2.0}
gas: {flow_mL_per_min: 60, temperature_C: 0, pressure_kPa: 101.325, inlet_ppm: {A: )"
                                                          + std::to_string(feedPpm) + R"(}}
initial_mg_per_L: {A: 44.0}
oh: {model: constant, concentration_mg_per_L: 1.7e-10}
time: {duration_h: 5, output_interval_min: 10}
solver: {method: )" + method + R"(, rk4_step_s: 20, rtol: 1e-10, atol_mol_per_L: 1e-18}
)");
}

Results runFile(const std::string& file)
{
    return runCase(CaseSource::load(file).build());
}

} // namespace

TEST(KineticsSolvers, FirstOrderDecayIsExponential)
{
    for (const std::string method : {"expm", "rk4", "cvode"})
    {
        const Results r = runFile(chainCase(method, 0.0));
        const double oh = 1.7e-10 / 1000.0 / 17.0; // mol/L
        const double a = 2e9 * oh, b = 0.5e9 * oh; // 1/s
        const double a0 = 1e-3;                    // 44 mg/L of a 44 g/mol species
        const double tol = method == "cvode" ? 1e-7 : 1e-9;
        for (std::size_t i = 0; i < r.t.size(); ++i)
        {
            const double t = r.t[i];
            const double cA = a0 * std::exp(-a * t);
            const double cB = a0 * a / (b - a) * (std::exp(-a * t) - std::exp(-b * t));
            EXPECT_NEAR(r.c[i][0], cA, tol * a0) << method << " t=" << t;
            EXPECT_NEAR(r.c[i][1], cB, tol * a0) << method << " t=" << t;
        }
    }
}

TEST(KineticsSolvers, FeedApproachesItsSteadyState)
{
    const Results r = runFile(chainCase("expm", 100.0));
    const double oh = 1.7e-10 / 1000.0 / 17.0;
    const double a = 2e9 * oh;
    const double feed = 101325.0 * 60e-6 / 60.0 / (gasConstant * 273.15) * 100e-6 / 2.0; // mol/(L s)
    const double a0 = 1e-3;
    for (std::size_t i = 0; i < r.t.size(); ++i)
    {
        const double t = r.t[i];
        const double cA = a0 * std::exp(-a * t) + feed / a * (1 - std::exp(-a * t));
        EXPECT_NEAR(r.c[i][0], cA, 1e-11 * a0);
    }
}

TEST(KineticsSolvers, AllThreeAgreeOnThePaperCase)
{
    const CaseSource src = CaseSource::load(kt::casesDir() + "/base_0.3mA_30mgL_30ppm.yaml");
    Case c = src.build();
    const Model model(c);
    const auto times = outputTimes(c.duration, c.outputInterval);
    const Trajectory ex = solveExpm(model, times);
    const Trajectory rk = solveRk4(model, times, 10.0);
    const Trajectory cv = solveCvode(model, times, 1e-10, 1e-18);
    const double scale = model.initialState().maxCoeff();
    for (std::size_t i = 0; i < times.size(); ++i)
    {
        EXPECT_LT((rk.y[i] - ex.y[i]).cwiseAbs().maxCoeff(), 1e-9 * scale);
        EXPECT_LT((cv.y[i] - ex.y[i]).cwiseAbs().maxCoeff(), 1e-6 * scale);
    }
}

TEST(KineticsSolvers, Rk4ConvergesAtFourthOrder)
{
    const CaseSource src = CaseSource::load(kt::casesDir() + "/base_0.3mA_30mgL_30ppm.yaml");
    const Case c = src.build({{"I", 0.5}});
    const Model model(c);
    const std::vector<double> times = {0.0, 3600.0, 7200.0};
    const Trajectory ex = solveExpm(model, times);
    std::vector<double> err;
    for (double h : {400.0, 200.0, 100.0, 50.0})
        err.push_back((solveRk4(model, times, h).y.back() - ex.y.back()).cwiseAbs().maxCoeff());
    for (std::size_t i = 1; i < err.size(); ++i)
    {
        const double order = std::log2(err[i - 1] / err[i]);
        EXPECT_NEAR(order, 4.0, 0.15) << "h ratio " << i;
    }
}

TEST(KineticsSolvers, CvodeReproducesRobertsonReference)
{
    // Robertson's stiff chemical kinetics; reference values at t = 1e11 from the
    // Test Set for IVP Solvers (Mazzia & Magherini, problem ROBER).
    kt::writeFile("rober_mech.yaml", R"(
name: Robertson
check_carbon: false
species:
  - {name: A, molar_mass_g_per_mol: 1, carbon: 0}
  - {name: B, molar_mass_g_per_mol: 1, carbon: 0}
  - {name: C, molar_mass_g_per_mol: 1, carbon: 0}
reactions:
  - {id: r1, equation: "A -> B", k: 0.04, units: 1/s}
  - {id: r2, equation: "B + B -> C + B", k: 3.0e7, units: L/mol/s}
  - {id: r3, equation: "B + C -> A + C", k: 1.0e4, units: L/mol/s}
)");
    const std::string file = kt::writeFile("rober.yaml", R"(
mechanism: rober_mech.yaml
reactor: {liquid_volume_L: 1}
initial_mol_per_L: {A: 1}
time: {duration_s: 1.0e11, output_interval_s: 1.0e10}
solver: {method: cvode, rtol: 1.0e-10, atol_mol_per_L: 1.0e-20}
)");
    const Case c = CaseSource::load(file).build();
    const Model model(c);
    EXPECT_FALSE(model.isLinear());
    const Trajectory tr = solveCvode(model, {0.0, 1e11}, 1e-10, 1e-20);
    const Eigen::VectorXd& y = tr.y.back();
    EXPECT_NEAR(y[0], 0.2083340149701255e-7, 1e-4 * 0.2083340149701255e-7);
    EXPECT_NEAR(y[1], 0.8333360770334713e-13, 1e-4 * 0.8333360770334713e-13);
    EXPECT_NEAR(y[2], 0.9999999791665050, 1e-10);
    EXPECT_NEAR(y.sum(), 1.0, 1e-12);
    // expm must refuse a nonlinear mechanism
    EXPECT_THROW(solve(model, {0.0, 1.0}, SolverOptions{"expm"}), procsim::InputError);
}

// Carbon is a linear invariant of the balances.  expm is exact for a linear
// system; RK4 (any Runge-Kutta method) and CVODE's BDF (any linear multistep
// method, with Newton corrections on an exact Jacobian) preserve linear
// invariants exactly, so only rounding is left: ~10 terms a step over at most
// a few thousand steps, a linear worst case of ~4e-12.  Hence 1e-11, two
// orders below what a non-conserving method would show at cvode's rtol.
constexpr double kCarbonRoundOff = 1e-11;

TEST(KineticsSolvers, CarbonBalanceClosesForEverySolver)
{
    const CaseSource src = CaseSource::load(kt::casesDir() + "/base_0.3mA_30mgL_30ppm.yaml");
    for (const char* method : {"expm", "rk4", "cvode"})
        for (double ppm : {0.0, 200.0})
        {
            Case c = src.build({{"gas.inlet_ppm.AD", ppm}});
            c.solver.method = method;
            const Results r = runCase(c);
            EXPECT_LT(maxCarbonError(r), kCarbonRoundOff) << method << " " << ppm;
            // mineralisation really happened (the balance is not trivially satisfied)
            EXPECT_GT(r.inorganicCarbon.back(), 0.5 * r.carbonInitial.back());
        }
}

TEST(KineticsSolvers, IntegratedOhWithFastScavengingMatchesPseudoSteadyOh)
{
    // OH as a species: production P, scavenging k_s [OH], consumption by the organics.  With
    // P / k_s equal to the paper's [OH] at 0.3 mA and k_s (1e10 1/s) far above the organics' OH
    // demand (sum k_i c_i <= 15.5e9 * 3.2e-4 = 5e6 1/s), [OH] stays within 0.05 % of P / k_s, so the
    // stiff nonlinear run must reproduce the linear pseudo-steady one to well under 2 %.
    const Results pss = runCase(CaseSource::load(kt::casesDir() + "/base_0.3mA_30mgL_30ppm.yaml").build());
    const Results dyn =
        runCase(CaseSource::load(kt::casesDir() + "/dynamic_oh_0.3mA_30mgL_30ppm.yaml").build());
    EXPECT_EQ(dyn.cas.solver.method, "cvode");
    for (double t : {3 * 3600.0, 8 * 3600.0})
        for (const char* q : {"PH", "AA", "CC", "TOC"})
            EXPECT_NEAR(dyn.value(q, t), pss.value(q, t), 0.02 * pss.value(q, t))
                << q << " at " << t / 3600 << " h";
    const std::size_t oh = dyn.cas.mech.index("OH", "");
    EXPECT_NEAR(dyn.c.back()[static_cast<Eigen::Index>(oh)], 1.547e-14, 1e-3 * 1.547e-14);
    EXPECT_LT(maxCarbonError(dyn), kCarbonRoundOff);
}

TEST(KineticsSolvers, FeedSupportedSteadyStateByHand)
{
    // Long after the phenol's carbon is gone, the fed acetaldehyde alone sets the state:
    // [AD] = F / ((k1 + k2)[OH]), [AA] = k1/k3 [AD], [UP_C1] = k2/k4 [AD], with
    // F = q_g C_in 10^-6 / W.  Base case: 100 mL/min at 25 C and 101.3 kPa, 30 ppm, 1 L, 0.3 mA.
    // The slowest time scale is 1/(k3 [OH]) = 3.6 h, so after 100 h the run is at the steady
    // state to far better than 1e-6.
    const double oh = 8.77e-10 * 0.3 / 17.007 / 1000.0;                 // mol/L
    const double qg = 101.3e3 * 100e-6 / 60.0 / (gasConstant * 298.15); // mol/s
    const double feed = qg * 30e-6 / 1.0;                               // mol/L/s
    const double k1 = 5e9, k2 = 4e9, k3 = 5e9, k4 = 8e9;
    const double ad = feed / ((k1 + k2) * oh), aa = k1 / k3 * ad, up = k2 / k4 * ad;
    const double toc = (2 * ad + 2 * aa + up) * carbonMolarMass * 1000.0; // mg C/L
    const Results r = runCase(
        CaseSource::load(kt::casesDir() + "/base_0.3mA_30mgL_30ppm.yaml").build({{"time.duration_h", 100}}));
    const double t = 100 * 3600.0;
    EXPECT_NEAR(r.value("AD", t), ad * 44.053e3, 1e-6 * ad * 44.053e3);
    EXPECT_NEAR(r.value("AA", t), aa * 60.052e3, 1e-6 * aa * 60.052e3);
    EXPECT_NEAR(r.value("TOC", t), toc, 1e-6 * toc);
    EXPECT_NEAR(toc, 0.79, 0.005); // the README's figure for the toc_plateau departure
}
