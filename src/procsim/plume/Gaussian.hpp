#pragma once
// ISCST3-style steady Gaussian plume (flat terrain, no plume rise):
//
//   C = Q D(x) / (2 pi u sigma_y sigma_z) exp(-y^2 / 2 sigma_y^2) V(z, h, sigma_z, z_i)
//
// with V the vertical term including reflection at the ground and at the
// mixing height z_i (images 2 i z_i +- h), replaced by uniform mixing
// sqrt(2 pi) sigma_z / z_i once sigma_z > 1.6 z_i; D(x) the source-depletion
// factor of dry deposition.  Stability: Pasquill-Gifford classes A..F (1..6)
// from the 10-m wind, cloud cover and the sun's elevation; dispersion: the
// rural curves of plume/Dispersion.hpp (ISC3's Pasquill-Gifford by default,
// or Briggs'), or sigma^2 = 2 K x / u for the slender-plume check against the
// Eulerian model.  Point sources; volume sources as virtual
// point sources (sigma_y0 = side/4.3, sigma_z0 = height/2.15 on the ground,
// /4.3 elevated); area sources integrated over an n x n subdivision.
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "plume/Dispersion.hpp"
#include "plume/Met.hpp"
#include "plume/Sites.hpp"

namespace procsim::plume
{

// Sun's elevation [deg] from latitude, day of year and local solar time [h].
double solarElevationDeg(double latitudeDeg, int dayOfYear, double solarHour);

// Pasquill-Gifford class 1..6 (A..F) from the Pasquill/Turner table.  Day
// (sun above the horizon): insolation strong above 60 deg of elevation,
// moderate 35-60, slight below 35, one step weaker with more than half the sky
// (> 4 oktas) covered; overcast (8 oktas) day or night is D.  Night: cloudy
// (>= 4 oktas) or clear.  Half classes of the table (A-B, B-C, C-D) are
// taken as the more stable one.
int stabilityClass(double u10, double cloudOktas, double sunElevationDeg);
char className(int cls);

// ISC rural wind-profile exponents for classes A..F
double ruralWindExponent(int cls);

// Vertical term V of the plume equation (ground and mixing-height images);
// mixingHeight <= 0 means no lid.
double verticalTerm(double z, double h, double sigmaZ, double mixingHeight);

struct GaussianOptions
{
    double latitudeDeg = 14.5;
    int startDayOfYear = 1;        // day of the first meteorology hour
    double startHour = 0;          // local solar time of the first hour [h]; hour n covers n..n+1
    double depositionVelocity = 0; // v_d [m/s] (0 = no depletion)
    int areaSubdivisions = 10;
    double minWind = 1.0;              // m/s, ISC's floor for the wind at release height
    double windExponent = -1;          // power-law exponent to the release height; < 0: ISC rural by class
    double reduction = 0;              // removed fraction of controlled emissions
    std::string curves = "isc3_rural"; // a name of DispersionCurves::curveNames()
    bool constantK = false;            // sigma^2 = 2 K x / u instead of the curves
    double kH = 200, kV = 1;
    bool mixingLidStable = false; // ISC: no lid for E and F
};

struct PlumeHour
{
    double u10 = 1, directionFrom = 0, mixingHeight = 1000;
    int cls = 4;
};

class GaussianModel
{
public:
    GaussianModel(std::vector<Source> sources, GaussianOptions options);
    ~GaussianModel();

    // Class and wind of one meteorology hour (index from the series start).
    PlumeHour hourConditions(const MetHour& m, int index) const;
    // Concentration [kg/m^3] at a receptor for one hour.
    double concentration(const PlumeHour& h, const Receptor& r) const;
    // Depletion factor Q(x)/Q0 of a point release at height h for class/wind
    double depletion(int cls, double u, double h, double x, double xzVirtual = 0) const;

    const GaussianOptions& options() const { return opt_; }
    std::string dispersionTitle() const;

private:
    struct Element;
    std::vector<Source> sources_;
    GaussianOptions opt_;
    std::unique_ptr<const DispersionCurves> curves_;
    std::vector<Element> elements_;
    struct Tables;
    std::unique_ptr<Tables> tables_;
};

} // namespace procsim::plume
