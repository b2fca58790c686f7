#pragma once
// Rural dispersion curves sigma_y(x), sigma_z(x) [m] of the Gaussian plume
// for the Pasquill-Gifford classes 1..6 (A..F), x the downwind distance [m].
// One class per set of curves; a case names it in `dispersion.model`.
//
//   isc3_rural    Pasquill-Gifford curves in Turner's fit, as ISC3 codes them
//                 (ISC3 user's guide vol. II, Tables 1-1 and 1-2): the ISCST3
//                 rural default, and ours
//   briggs_rural  Briggs' (1973) open-country interpolation formulas
#include <memory>
#include <string>
#include <vector>

namespace procsim::plume
{

class DispersionCurves
{
public:
    virtual ~DispersionCurves() = default;
    virtual double sigmaY(int cls, double x) const = 0;
    virtual double sigmaZ(int cls, double x) const = 0;
    virtual std::string title() const = 0; // for summaries

    // The curves called `name`, or nullptr for a name not in curveNames().
    static std::unique_ptr<DispersionCurves> create(const std::string& name);
    static const std::vector<std::string>& curveNames();
};

// ISC3 rural, x in km inside:
//   sigma_y = 465.11628 x tan(TH),  TH = 0.017453293 (c - d ln x)  [rad]
//   sigma_z = a x^b with a, b by class and distance range; a range's upper
//   bound belongs to the next range (the breaks are continuous to ~1e-4);
//   classes A-C capped at 5000 m.
class Isc3RuralCurves : public DispersionCurves
{
public:
    double sigmaY(int cls, double x) const override;
    double sigmaZ(int cls, double x) const override;
    std::string title() const override { return "ISC3 rural (Pasquill-Gifford)"; }
};

// Briggs rural: sigma_y = a x (1 + 1e-4 x)^-1/2; sigma_z per class.
class BriggsRuralCurves : public DispersionCurves
{
public:
    double sigmaY(int cls, double x) const override;
    double sigmaZ(int cls, double x) const override;
    std::string title() const override { return "Briggs rural"; }
};

} // namespace procsim::plume
