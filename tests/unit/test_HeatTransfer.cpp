// Heat-transfer correlations at two states of the draft-plate dryer, evaluated
// by hand from the published formulas, their zero-slip limits, and the
// spout/downcomer region rule on a synthetic vessel.
//
// Air at 65.6 C: rho 1.0324, mu 2.029e-5, cp 1008.6, k_c 0.02917; d = 8 mm.
//   Pr = 1008.6 2.029e-5/0.02917 = 0.0204645/0.02917 = 0.701560
//   Pr^(1/3) = 0.888563,  k_c/d = 0.02917/8e-3 = 3.64625
// Spout:     eps 0.95, slip 15:  Re = 0.95 1.0324 15 8e-3/2.029e-5
//                                   = 0.117694/2.029e-5 = 5800.57
// Downcomer: eps 0.45, slip 0.7: Re = 0.45 1.0324 0.7 8e-3/2.029e-5
//                                   = 2.60165e-3/2.029e-5 = 128.223

#include "HeatTransferModel.hpp"
#include "InputError.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>
#include <utility>

using namespace spoutlab;

namespace
{

const GasThermalProperties air{1.0324, 2.029e-5, 1008.6, 0.02917};
const double d = 8e-3;

HeatTransferCell cell(double eps, double slip, Vec3 centre = {})
{
    return {centre, eps, d, slip};
}
const HeatTransferCell spoutCell = cell(0.95, 15.0);
const HeatTransferCell downcomerCell = cell(0.45, 0.7);

std::unique_ptr<HeatTransferModel> make(const std::string& name, Parameters p = Parameters("test"))
{
    return HeatTransferModel::New(name, p);
}

double h(const std::string& name, const HeatTransferCell& c)
{
    return make(name)->h(c, air);
}

void expectRel(double value, double expected, double tol)
{
    EXPECT_LT(std::fabs(value - expected), tol * std::fabs(expected)) << value << " vs " << expected;
}

} // namespace

// --- helpers -------------------------------------------------------------------

TEST(HeatTransferHelpers, ReynoldsAndPrandtlByHand)
{
    expectRel(heatTransferReynolds(spoutCell, air), 5800.57, 1e-6);
    expectRel(heatTransferReynolds(downcomerCell, air), 128.223, 1e-5);
    EXPECT_EQ(heatTransferReynolds(cell(0.6, 0.0), air), 0.0);
    expectRel(air.prandtl(), 0.701560, 1e-6);
}

// --- Ranz-Marshall ---------------------------------------------------------------

TEST(RanzMarshall, SpoutAndDowncomerByHand)
{
    // Spout: sqrt(5800.57) = 76.1615, Nu = 2 + 0.6 0.888563 76.1615 = 2 + 40.6046 = 42.6046,
    //        h = 42.6046 3.64625 = 155.347
    expectRel(h("RanzMarshall", spoutCell), 155.347, 1e-5);
    // Downcomer: sqrt(128.223) = 11.3236, Nu = 2 + 0.533138 11.3236 = 8.03702,
    //            h = 8.03702 3.64625 = 29.3050
    expectRel(h("RanzMarshall", downcomerCell), 29.3050, 1e-5);
}

TEST(RanzMarshall, ZeroSlipIsConductionNuTwo)
{
    // Nu -> 2: h = 2 k_c/d = 7.2925, whatever the voidage.
    expectRel(h("RanzMarshall", cell(0.95, 0.0)), 7.2925, 1e-12);
    expectRel(h("RanzMarshall", cell(0.45, 0.0)), 7.2925, 1e-12);
    // Just above zero slip it is still 2 to first order: Re = 6.7e-7, Nu - 2 = 4.4e-4.
    expectRel(h("RanzMarshall", cell(0.45, 1e-9)), 7.2925, 1e-3);
}

// --- Sartori ---------------------------------------------------------------------

TEST(Sartori, SpoutAndDowncomerByHand)
{
    // 1.54 Pr^(1/3) = 1.54 0.888563 = 1.368387
    // Spout: 5800.57^0.57 = exp(0.57 8.66572) = 139.694, Nu = 1.368387 139.694 = 191.156,
    //        h = 191.156 3.64625 = 697.001
    expectRel(h("Sartori", spoutCell), 697.001, 1e-5);
    // Downcomer: 128.223^0.57 = exp(0.57 4.85377) = 15.9053, Nu = 21.7646, h = 79.3590
    expectRel(h("Sartori", downcomerCell), 79.3590, 1e-5);
}

TEST(Sartori, ZeroSlipGivesZero)
{
    // No conduction term: Re^0.57 = 0.
    EXPECT_EQ(h("Sartori", cell(0.45, 0.0)), 0.0);
}

// --- Gunn ------------------------------------------------------------------------

TEST(Gunn, SpoutAndDowncomerByHand)
{
    // eps 0.95: a = 7 - 9.5 + 4.5125 = 2.0125, b = 1.33 - 2.28 + 1.083 = 0.133
    //   Re^0.2 = 5.65841, Re^0.7 = 430.953
    //   Nu = 2.0125 (1 + 0.7 5.65841 0.888563) + 0.133 430.953 0.888563
    //      = 2.0125 4.51949 + 50.9295 = 9.09547 + 50.9295 = 60.0250, h = 218.866
    expectRel(h("Gunn", spoutCell), 218.866, 1e-5);
    // eps 0.45: a = 7 - 4.5 + 1.0125 = 3.5125, b = 1.33 - 1.08 + 0.243 = 0.493
    //   Re^0.2 = 2.63994, Re^0.7 = 29.8935
    //   Nu = 3.5125 (1 + 0.7 2.63994 0.888563) + 0.493 29.8935 0.888563
    //      = 3.5125 2.64202 + 13.0952 = 9.28010 + 13.0952 = 22.3753, h = 81.5859
    expectRel(h("Gunn", downcomerCell), 81.5859, 1e-5);
}

TEST(Gunn, ZeroSlipLimits)
{
    // eps = 1, Re = 0: a = 7 - 10 + 5 = 2, so Nu = 2, the single sphere.
    expectRel(h("Gunn", cell(1.0, 0.0)), 7.2925, 1e-12);
    // eps 0.45, Re = 0: Nu = a = 3.5125, h = 3.5125 3.64625 = 12.8075
    expectRel(h("Gunn", cell(0.45, 0.0)), 12.8075, 1e-5);
}

// --- the correlation as Nu(Re, Pr), and mass transfer ---------------------------

// h must stay the value it was before the correlations became nusselt(): the
// solver's heat-transfer results depend on it to the bit. Each correlation's
// published expression, written out here as h() computed it, must agree
// exactly (EXPECT_EQ, not NEAR) on cells from packed to dilute. The inputs
// pass through a volatile so that the compiler cannot fold the test's side at
// compile time, where pow and cbrt are rounded correctly and the library's at
// run time may differ in the last bit.
TEST(HeatTransferModel, HIsTheCorrelationsExpressionToTheBit)
{
    auto rm = make("RanzMarshall"), sartori = make("Sartori"), gunn = make("Gunn");
    for (double epsValue : {0.36, 0.45, 0.7, 0.95, 1.0})
    {
        for (double slipValue : {0.0, 1e-6, 0.7, 3.0, 15.0})
        {
            volatile double opaque[3] = {epsValue, slipValue, air.prandtl()};
            const double eps = opaque[0];
            const HeatTransferCell c = cell(eps, opaque[1]);
            const double re = heatTransferReynolds(c, air), pr = opaque[2];
            const double nuRm = 2.0 + 0.6 * std::cbrt(pr) * std::sqrt(re);
            EXPECT_EQ(rm->h(c, air), nuRm * air.kappa / c.diameter);
            EXPECT_EQ(rm->nusselt(c, re, pr), nuRm);
            const double nuSartori = 1.54 * std::cbrt(pr) * std::pow(re, 0.57);
            EXPECT_EQ(sartori->h(c, air), nuSartori * air.kappa / c.diameter);
            const double pr3 = std::cbrt(pr);
            const double lowRe = (7.0 - 10.0 * eps + 5.0 * eps * eps) * (1.0 + 0.7 * std::pow(re, 0.2) * pr3);
            const double highRe = (1.33 - 2.4 * eps + 1.2 * eps * eps) * std::pow(re, 0.7) * pr3;
            EXPECT_EQ(gunn->h(c, air), (lowRe + highRe) * air.kappa / c.diameter);
        }
    }
}

// Water vapour, D_v = 3.0e-5 m^2/s, in the air above:
//   Sc = 2.029e-5/(1.0324 3.0e-5) = 0.655108, Sc^(1/3) = 0.868502
// Ranz-Marshall, spout: Sh = 2 + 0.6 0.868502 76.1615 = 41.6879,
//   k_m = 41.6879 3.0e-5/8e-3 = 0.156329 m/s
// Sartori, downcomer: Sh = 1.54 0.868502 15.9053 = 21.2732, k_m = 0.0797745 m/s
TEST(HeatTransferModel, MassTransferIsTheSherwoodFormByHand)
{
    const double dv = 3.0e-5;
    expectRel(make("RanzMarshall")->massTransferCoefficient(spoutCell, air, dv), 0.156329, 1e-5);
    expectRel(make("Sartori")->massTransferCoefficient(downcomerCell, air, dv), 0.0797745, 1e-5);
    // the region rule uses the cell's own correlation for mass as for heat
    auto rule = make("spoutDowncomer", [] {
        Parameters p("couplingProperties/spoutDowncomerProps");
        p.set("region", "voidage").set("spoutVoidage", "0.8");
        return p;
    }());
    expectRel(rule->massTransferCoefficient(spoutCell, air, dv), 0.156329, 1e-5);
    expectRel(rule->massTransferCoefficient(downcomerCell, air, dv), 0.0797745, 1e-5);
}

// Lewis number 1: a vapour diffusing as fast as heat (D_v = k_c/(rho c_p),
// so Sc = Pr) has k_m rho c_p = h, for every correlation and cell.
TEST(HeatTransferModel, UnitLewisNumberGivesTheChiltonColburnIdentity)
{
    const double alpha = air.kappa / (air.rho * air.cp);
    for (const char* n : {"RanzMarshall", "Sartori", "Gunn"})
    {
        auto m = make(n);
        for (const HeatTransferCell& c : {spoutCell, downcomerCell, cell(0.6, 0.0)})
        {
            const double hc = m->h(c, air);
            EXPECT_NEAR(m->massTransferCoefficient(c, air, alpha) * air.rho * air.cp, hc, 1e-12 * (1.0 + hc))
                << n;
        }
    }
}

// --- selection ---------------------------------------------------------------------

TEST(HeatTransferModels, SelectedByName)
{
    const auto names = HeatTransferModel::available();
    EXPECT_EQ(names, (std::vector<std::string>{"Gunn", "RanzMarshall", "Sartori", "spoutDowncomer"}));
    for (const char* n : {"RanzMarshall", "Sartori", "Gunn"})
    {
        auto m = make(n);
        EXPECT_EQ(m->name(), n);
        EXPECT_EQ(m->region(spoutCell), -1) << n; // one correlation everywhere
    }
}

TEST(HeatTransferModels, UnknownNameListsTheChoices)
{
    try
    {
        make("Whitaker", Parameters("constant/couplingProperties/WhitakerProps"));
        FAIL() << "no InputError";
    }
    catch (const InputError& e)
    {
        EXPECT_STREQ(e.what(), "constant/couplingProperties: key 'heatTransferModel' expected one of Gunn, "
                               "RanzMarshall, Sartori, spoutDowncomer, got 'Whitaker'");
    }
}

// --- spoutDowncomer -----------------------------------------------------------------

namespace
{

// Draft-plate vessel: plates' inner faces at x = +-0.0275, their upper edge
// (the fountain base) at z = 0.912.
Parameters geometryProps()
{
    Parameters p("couplingProperties/spoutDowncomerProps");
    p.set("region", "geometry").set("spoutHalfWidth", "0.0275").set("fountainBase", "0.912");
    return p;
}

Parameters voidageProps(const std::string& threshold = "0.8")
{
    Parameters p("couplingProperties/spoutDowncomerProps");
    p.set("region", "voidage").set("spoutVoidage", threshold);
    return p;
}

} // namespace

TEST(SpoutDowncomer, GeometryRuleOnADraftPlateVessel)
{
    // 90 x 50 cells over x in [-0.2475, 0.2475], z in [0, 1.2]: dx = 0.0055,
    // dz = 0.024, centres x_i = -0.2475 + 0.0055 (i + 1/2), z_j = 0.024 (j + 1/2).
    // |x_i| <= 0.0275 for i = 40..49 (|x| = 0.00275 ... 0.02475, the next 0.03025);
    // z_j >= 0.912 for j = 38..49 (z_37 = 0.900, z_38 = 0.924).
    // Spout: 10 columns x 50 rows + 80 columns x 12 rows = 500 + 960 = 1460.
    auto rule = make("spoutDowncomer", geometryProps());
    for (const HeatTransferCell& state : {spoutCell, downcomerCell})
    {
        const double hSpout = h("RanzMarshall", state), hDown = h("Sartori", state);
        int spoutCells = 0;
        for (int i = 0; i < 90; ++i)
        {
            for (int j = 0; j < 50; ++j)
            {
                HeatTransferCell c = state;
                c.centre = {-0.2475 + 0.0055 * (i + 0.5), 0.0, 0.024 * (j + 0.5)};
                const bool spout = (i >= 40 && i <= 49) || j >= 38;
                EXPECT_EQ(rule->region(c), spout ? 1 : 0) << i << ", " << j;
                EXPECT_EQ(rule->h(c, air), spout ? hSpout : hDown) << i << ", " << j;
                spoutCells += rule->region(c);
            }
        }
        EXPECT_EQ(spoutCells, 1460);
    }
}

TEST(SpoutDowncomer, GeometryBoundariesAndAxis)
{
    auto rule = make("spoutDowncomer", geometryProps());
    EXPECT_EQ(rule->region(cell(0.45, 0.7, {0.0275, 0.0, 0.5})), 1);  // on the plate's face
    EXPECT_EQ(rule->region(cell(0.45, 0.7, {-0.0276, 0.0, 0.5})), 0); // just behind it
    EXPECT_EQ(rule->region(cell(0.45, 0.7, {0.2, 0.0, 0.912})), 1);   // at the fountain base
    EXPECT_EQ(rule->region(cell(0.45, 0.7, {0.2, 0.0, 0.911})), 0);
    // The voidage plays no part: a dilute cell behind the plates is downcomer.
    EXPECT_EQ(rule->region(cell(0.99, 15.0, {0.2, 0.0, 0.5})), 0);

    Parameters shifted = geometryProps();
    shifted.set("spoutAxis", "0.1").set("spoutHalfWidth", "0.02");
    auto off = make("spoutDowncomer", shifted);
    EXPECT_EQ(off->region(cell(0.45, 0.7, {0.115, 0.0, 0.5})), 1);
    EXPECT_EQ(off->region(cell(0.45, 0.7, {0.0, 0.0, 0.5})), 0);
}

TEST(SpoutDowncomer, VoidageRule)
{
    auto rule = make("spoutDowncomer", voidageProps("0.8"));
    EXPECT_EQ(rule->region(cell(0.8, 1.0)), 1); // the threshold counts as spout
    EXPECT_EQ(rule->region(cell(0.79, 1.0)), 0);
    EXPECT_EQ(rule->region(spoutCell), 1);
    EXPECT_EQ(rule->region(downcomerCell), 0);
    // The hand values above: Ranz-Marshall in the spout, Sartori in the downcomer.
    expectRel(rule->h(spoutCell, air), 155.347, 1e-5);
    expectRel(rule->h(downcomerCell, air), 79.3590, 1e-5);
}

TEST(SpoutDowncomer, SubModelsAreChosenByName)
{
    Parameters p = voidageProps();
    p.set("spout", "Gunn").set("downcomer", "RanzMarshall");
    auto rule = make("spoutDowncomer", p);
    expectRel(rule->h(spoutCell, air), 218.866, 1e-5);
    expectRel(rule->h(downcomerCell, air), 29.3050, 1e-5);
}

TEST(SpoutDowncomer, BadParametersNameTheKey)
{
    Parameters missingWidth("couplingProperties/spoutDowncomerProps");
    missingWidth.set("region", "geometry").set("fountainBase", "0.912");
    Parameters zeroWidth = geometryProps();
    zeroWidth.set("spoutHalfWidth", "0");
    Parameters missingBase("couplingProperties/spoutDowncomerProps");
    missingBase.set("region", "geometry").set("spoutHalfWidth", "0.0275");
    Parameters nonsense = voidageProps();
    nonsense.set("region", "nonsense");
    Parameters noRegion("couplingProperties/spoutDowncomerProps");
    Parameters nested = voidageProps();
    nested.set("spout", "spoutDowncomer");
    Parameters unknownSub = voidageProps();
    unknownSub.set("downcomer", "Whitaker");
    const std::pair<Parameters, const char*> cases[] = {
        {missingWidth, "spoutHalfWidth"},
        {zeroWidth, "spoutHalfWidth"},
        {missingBase, "fountainBase"},
        {nonsense, "region"},
        {noRegion, "region"},
        {voidageProps("1.5"), "spoutVoidage"},
        {voidageProps("0"), "spoutVoidage"},
        {nested, "spout"},
        {unknownSub, "downcomer"},
    };
    for (const auto& [props, key] : cases)
    {
        try
        {
            make("spoutDowncomer", props);
            ADD_FAILURE() << "no InputError for " << key;
        }
        catch (const InputError& e)
        {
            const std::string msg = e.what();
            const std::string prefix =
                std::string("couplingProperties/spoutDowncomerProps: key '") + key + "'";
            EXPECT_EQ(msg.rfind(prefix, 0), 0u) << msg;
            EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
        }
    }
}
