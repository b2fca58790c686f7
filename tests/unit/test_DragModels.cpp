// Drag laws at points evaluated by hand from the published formulas, and the
// two limits that fix the beta convention: the packed bed (Ergun) and the
// single sphere (C_d pi d^2/4 rho w^2/2).

#include "DragModel.hpp"
#include "InputError.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

using namespace spoutlab;

namespace
{

const double pi = std::acos(-1.0);
const GasProperties air{1.2, 1.8e-5};
const double d = 8e-3;

std::unique_ptr<DragModel> make(const std::string& name, Parameters p = Parameters("test"))
{
    return DragModel::New(name, p);
}

double beta(const DragModel& m, double eps, double w, double diameter = d)
{
    return m.beta(DragState{eps, diameter, w}, air);
}

// Hand formulas, written out as in the papers (C_d itself, not C_d |w|).
double ergunBeta(double eps, double w)
{
    return 150.0 * (1 - eps) * (1 - eps) * air.mu / (eps * d * d) + 1.75 * (1 - eps) * air.rho * w / d;
}

double schillerNaumann(double re)
{
    return re < 1000 ? 24.0 / re * (1 + 0.15 * std::pow(re, 0.687)) : 0.44;
}

double wenYuBeta(double eps, double w)
{
    const double re = eps * air.rho * w * d / air.mu;
    return 0.75 * schillerNaumann(re) * air.rho * eps * (1 - eps) * w / d * std::pow(eps, -2.65);
}

double relDiff(double a, double b)
{
    return std::fabs(a - b) / std::fabs(b);
}

} // namespace

// --- Gidaspow ---------------------------------------------------------------

TEST(Gidaspow, DenseIsErgunByHand)
{
    // 150 (0.6)^2 1.8e-5/(0.4 (8e-3)^2) = 9.72e-4/2.56e-5 = 37.96875
    // 1.75 0.6 1.2 1/8e-3                                   = 157.5
    EXPECT_NEAR(beta(*make("Gidaspow"), 0.4, 1.0), 37.96875 + 157.5, 1e-10);
}

TEST(Gidaspow, DiluteWenYuBelowAndAboveRe1000)
{
    auto g = make("Gidaspow");
    // eps 0.9, w 1: Re = 0.9 1.2 1 8e-3/1.8e-5 = 480 -> Schiller-Naumann
    EXPECT_LT(relDiff(beta(*g, 0.9, 1.0), wenYuBeta(0.9, 1.0)), 1e-13);
    // w 5: Re = 2400 -> C_d = 0.44
    const double expected = 0.75 * 0.44 * 1.2 * 0.9 * 0.1 * 5.0 / d * std::pow(0.9, -2.65);
    EXPECT_LT(relDiff(beta(*g, 0.9, 5.0), expected), 1e-13);
}

TEST(Gidaspow, ZeroSlipIsFiniteStokesLimit)
{
    auto g = make("Gidaspow");
    // Wen-Yu with C_d = 24/Re: beta -> 18 mu (1-eps) eps^-2.65/d^2.
    const double stokes = 18.0 * air.mu * 0.1 * std::pow(0.9, -2.65) / (d * d);
    EXPECT_LT(relDiff(beta(*g, 0.9, 0.0), stokes), 1e-13);
    EXPECT_LT(relDiff(beta(*g, 0.9, 1e-9), stokes), 1e-5);
    // Ergun keeps only its viscous term.
    EXPECT_LT(relDiff(beta(*g, 0.5, 0.0), 150.0 * 0.25 * air.mu / (0.5 * d * d)), 1e-13);
}

TEST(Gidaspow, SharpSwitchJumpsAtPointEight)
{
    auto g = make("Gidaspow");
    const double below = beta(*g, std::nextafter(0.8, 0.0), 1.0);
    const double at = beta(*g, 0.8, 1.0);
    EXPECT_LT(relDiff(below, ergunBeta(0.8, 1.0)), 1e-9);
    EXPECT_LT(relDiff(at, wenYuBeta(0.8, 1.0)), 1e-13);
    // By hand: Ergun 2.109 + 52.5 = 54.61, Wen-Yu (Re 426.7, C_d 0.597) 19.42,
    // so beta drops by a factor of about 2.8 across the switch.
    EXPECT_NEAR(below / at, 2.81, 0.01);
}

TEST(Gidaspow, SwitchPointIsAParameter)
{
    Parameters p("GidaspowProps");
    p.set("epsilonSwitch", "0.7");
    auto g = make("Gidaspow", p);
    EXPECT_LT(relDiff(beta(*g, 0.75, 1.0), wenYuBeta(0.75, 1.0)), 1e-13);
    EXPECT_LT(relDiff(beta(*g, 0.65, 1.0), ergunBeta(0.65, 1.0)), 1e-13);
}

TEST(Gidaspow, SmoothSwitchIsContinuousAndBlends)
{
    Parameters p("GidaspowProps");
    p.set("switch", "smooth");
    auto g = make("Gidaspow", p);
    const double left = beta(*g, 0.8 - 1e-9, 1.0);
    const double right = beta(*g, 0.8 + 1e-9, 1.0);
    EXPECT_LT(relDiff(left, right), 1e-6);
    // At the switch the weight is exactly 1/2.
    EXPECT_LT(relDiff(beta(*g, 0.8, 1.0), 0.5 * (ergunBeta(0.8, 1.0) + wenYuBeta(0.8, 1.0))), 1e-13);
    // Elsewhere the Huilin-Gidaspow weight phi = 1/2 + atan(262.5 (eps - 0.8))/pi.
    const double phi = 0.5 + std::atan(262.5 * (0.4 - 0.8)) / pi;
    const double blended = (1 - phi) * ergunBeta(0.4, 1.0) + phi * wenYuBeta(0.4, 1.0);
    EXPECT_LT(relDiff(beta(*g, 0.4, 1.0), blended), 1e-13);
}

// beta (u_s/eps)/eps, the pressure gradient of a packed bed at rest, must be
// the Ergun equation for the superficial velocity u_s.
TEST(Gidaspow, PackedBedReproducesErgun)
{
    auto g = make("Gidaspow");
    const double eps = 0.4;
    for (double us : {0.01, 0.5, 2.0})
    {
        const double gradP = beta(*g, eps, us / eps) * (us / eps) / eps;
        const double ergun = 150.0 * (1 - eps) * (1 - eps) * air.mu * us / (eps * eps * eps * d * d)
                             + 1.75 * (1 - eps) * air.rho * us * us / (eps * eps * eps * d);
        EXPECT_LT(relDiff(gradP, ergun), 1e-12) << "u_s = " << us;
    }
}

// --- single-particle limit ----------------------------------------------------

namespace
{

// Force on one particle, V beta/(1-eps) w, for eps -> 1.
double singleParticleForce(const DragModel& m, double w)
{
    const double eps = 1.0 - 1e-9;
    const double volume = pi * d * d * d / 6.0;
    return volume * beta(m, eps, w) / (1.0 - eps) * w;
}

double sphereDrag(double cd, double w)
{
    return cd * pi * d * d / 4.0 * 0.5 * air.rho * w * w;
}

} // namespace

TEST(SingleParticleLimit, GidaspowGivesSchillerNaumann)
{
    auto g = make("Gidaspow");
    for (double w : {0.1, 1.0, 10.0})
    { // Re = 53, 533, 5333
        const double re = air.rho * w * d / air.mu;
        EXPECT_LT(relDiff(singleParticleForce(*g, w), sphereDrag(schillerNaumann(re), w)), 1e-7) << w;
    }
}

TEST(SingleParticleLimit, DiFeliceGivesDallavalle)
{
    auto m = make("DiFelice");
    for (double w : {0.1, 1.0, 10.0})
    {
        const double re = air.rho * w * d / air.mu;
        const double cd = std::pow(0.63 + 4.8 / std::sqrt(re), 2);
        EXPECT_LT(relDiff(singleParticleForce(*m, w), sphereDrag(cd, w)), 1e-7) << w;
    }
}

TEST(SingleParticleLimit, BeetstraGivesItsIsolatedSphereLaw)
{
    // phi -> 0: F = 1 + 0.413 Re/24 (1 + 8.4 Re^-0.343)/(1 + Re^-1/2), force = 3 pi mu d w F.
    // The law approaches it like 1.5 sqrt(phi) (its eps^2 (1 + 1.5 sqrt(phi))
    // term), so at phi = 1e-9 the tolerance is 2 sqrt(phi) rather than O(phi).
    auto m = make("Beetstra");
    const double tolerance = 2.0 * std::sqrt(1e-9);
    for (double w : {0.1, 1.0, 10.0})
    {
        const double re = air.rho * w * d / air.mu;
        const double f =
            1.0 + 0.413 * re / 24.0 * (1.0 + 8.4 * std::pow(re, -0.343)) / (1.0 + std::pow(re, -0.5));
        EXPECT_LT(relDiff(singleParticleForce(*m, w), 3.0 * pi * air.mu * d * w * f), tolerance) << w;
    }
}

// --- Di Felice and Beetstra at hand-computed points ---------------------------

TEST(DiFelice, HandPoint)
{
    // eps 0.6, w 0.5: Re = 0.6 1.2 0.5 8e-3/1.8e-5 = 160
    const double re = 160.0;
    const double cd = std::pow(0.63 + 4.8 / std::sqrt(re), 2);                          // 1.01904
    const double chi = 3.7 - 0.65 * std::exp(-0.5 * std::pow(1.5 - std::log10(re), 2)); // 3.19269
    const double expected = 0.75 * cd * air.rho * 0.4 * std::pow(0.6, 2.0 - chi) * 0.5 / d;
    const double b = beta(*make("DiFelice"), 0.6, 0.5);
    EXPECT_LT(relDiff(b, expected), 1e-12);
    EXPECT_NEAR(b, 42.17, 0.01); // evaluated on paper
}

TEST(DiFelice, ZeroSlipIsFinite)
{
    // Re -> 0: chi -> 3.7 and C_d |w| -> 4.8^2 mu/(eps rho d).
    const double eps = 0.6;
    const double expected = 0.75 * air.rho * (1 - eps) * std::pow(eps, 2.0 - 3.7) / d
                            * (4.8 * 4.8 * air.mu / (eps * air.rho * d));
    EXPECT_LT(relDiff(beta(*make("DiFelice"), eps, 0.0), expected), 1e-13);
}

TEST(Beetstra, HandPoint)
{
    // eps 0.6 (phi 0.4), Re 160, in the published form with negative powers of Re.
    const double eps = 0.6, phi = 0.4, re = 160.0;
    const double f = 10 * phi / (eps * eps) + eps * eps * (1 + 1.5 * std::sqrt(phi))
                     + 0.413 * re / (24 * eps * eps) * (1 / eps + 3 * eps * phi + 8.4 * std::pow(re, -0.343))
                           / (1 + std::pow(10.0, 3 * phi) * std::pow(re, -(1 + 4 * phi) / 2));
    const double expected = 18.0 * air.mu * eps * phi * f / (d * d);
    const double b = beta(*make("Beetstra"), eps, 0.5);
    EXPECT_LT(relDiff(b, expected), 1e-12);
    EXPECT_NEAR(b, 49.46, 0.01); // F = 40.71 evaluated on paper
}

TEST(Beetstra, ZeroSlipIsTheStokesArrayLimit)
{
    const double eps = 0.6, phi = 0.4;
    const double f = 10 * phi / (eps * eps) + eps * eps * (1 + 1.5 * std::sqrt(phi));
    EXPECT_LT(relDiff(beta(*make("Beetstra"), eps, 0.0), 18.0 * air.mu * eps * phi * f / (d * d)), 1e-13);
}

// --- all models -----------------------------------------------------------------

TEST(DragModels, PositiveAndFiniteOverOperatingRange)
{
    Parameters smooth("GidaspowProps");
    smooth.set("switch", "smooth");
    std::unique_ptr<DragModel> models[] = {make("Gidaspow"), make("Gidaspow", smooth), make("DiFelice"),
                                           make("Beetstra")};
    for (const auto& m : models)
    {
        for (double eps = 0.3; eps < 1.0; eps += 0.025)
        {
            for (double w : {0.0, 1e-9, 1e-3, 0.1, 1.0, 5.0, 20.0, 50.0})
            {
                for (double dp : {1e-4, 8e-3})
                {
                    const double b = beta(*m, eps, w, dp);
                    EXPECT_TRUE(std::isfinite(b) && b > 0.0) << m->name() << " eps " << eps << " w " << w;
                }
            }
        }
        const double nearlyEmpty = beta(*m, 1.0 - 1e-12, 50.0);
        EXPECT_TRUE(std::isfinite(nearlyEmpty) && nearlyEmpty > 0.0) << m->name();
    }
}

// Every law joins the registry from its own file; a law whose file the link
// left out would be missing here.
TEST(DragModels, SelectedByName)
{
    const std::vector<std::string> names = DragModel::available();
    EXPECT_EQ(names, (std::vector<std::string>{"Beetstra", "DiFelice", "Gidaspow"}));
    for (const auto& n : names) EXPECT_EQ(make(n)->name(), n);
}

TEST(DragModels, UnknownNameListsTheChoices)
{
    try
    {
        make("WenYu", Parameters("constant/couplingProperties/WenYuProps"));
        FAIL() << "no InputError";
    }
    catch (const InputError& e)
    {
        EXPECT_STREQ(e.what(),
                     "constant/couplingProperties: key 'dragModel' expected one of Beetstra, DiFelice, "
                     "Gidaspow, got 'WenYu'");
    }
}

TEST(DragModels, BadParametersNameTheKey)
{
    Parameters badSwitch("couplingProperties/GidaspowProps");
    badSwitch.set("switch", "blend");
    Parameters badNumber("couplingProperties/GidaspowProps");
    badNumber.set("epsilonSwitch", "abc");
    Parameters outOfRange("couplingProperties/GidaspowProps");
    outOfRange.set("epsilonSwitch", "1.5");
    for (const auto* p : {&badSwitch, &badNumber, &outOfRange})
    {
        try
        {
            make("Gidaspow", *p);
            FAIL() << "no InputError";
        }
        catch (const InputError& e)
        {
            const std::string msg = e.what();
            EXPECT_EQ(msg.rfind("couplingProperties/GidaspowProps: key '", 0), 0u) << msg;
        }
    }
}
