#include "SphereSampling.hpp"

#include "InputError.hpp"

#include <cmath>
#include <string>

namespace spoutlab
{

namespace
{

const double pi = std::acos(-1.0);

// Antiderivative of sqrt(1 - z^2): the in-plane weight of a band when the
// direction is integrated over dz.
double sinThetaIntegral(double z)
{
    return 0.5 * (z * std::sqrt(1.0 - z * z) + std::asin(z));
}

bool isFullCircle(const BallSector& s)
{
    return s.phiHigh - s.phiLow >= 2.0 * pi;
}

void addShell(std::vector<BallSector>& out, double rIn, double rOut, int nRings, int nAz, double phiOffset)
{
    const int perShell = 2 + nRings * nAz;
    const double capHeight = 2.0 / perShell; // in z = cos(theta)
    const double bandHeight = (2.0 - 2.0 * capHeight) / nRings;
    const double dPhi = 2.0 * pi / nAz;
    out.push_back({rIn, rOut, 1.0 - capHeight, 1.0, 0.0, 2.0 * pi});
    for (int band = 0; band < nRings; ++band)
    {
        const double zHigh = 1.0 - capHeight - band * bandHeight;
        const double zLow = band + 1 == nRings ? -1.0 + capHeight : zHigh - bandHeight;
        for (int m = 0; m < nAz; ++m)
        {
            out.push_back({rIn, rOut, zLow, zHigh, phiOffset + m * dPhi, phiOffset + (m + 1) * dPhi});
        }
    }
    out.push_back({rIn, rOut, -1.0, -1.0 + capHeight, 0.0, 2.0 * pi});
}

} // namespace

double BallSector::volume() const
{
    const double radial = (std::pow(rOuter, 3) - std::pow(rInner, 3)) / 3.0;
    return radial * (zHigh - zLow) * (phiHigh - phiLow);
}

Vec3 BallSector::centroid() const
{
    const double meanRadius =
        0.75 * (std::pow(rOuter, 4) - std::pow(rInner, 4)) / (std::pow(rOuter, 3) - std::pow(rInner, 3));
    const double solidAngle = (zHigh - zLow) * (phiHigh - phiLow);
    Vec3 direction{0.0, 0.0, 0.5 * (zHigh * zHigh - zLow * zLow) * (phiHigh - phiLow)};
    // A full circle has no in-plane mean; set it to exactly zero rather than
    // sin(2 pi) - sin(0) ~ 1e-16, so the cap points sit exactly on the axis.
    if (!isFullCircle(*this))
    {
        const double band = sinThetaIntegral(zHigh) - sinThetaIntegral(zLow);
        direction.x = band * (std::sin(phiHigh) - std::sin(phiLow));
        direction.y = band * (std::cos(phiLow) - std::cos(phiHigh));
    }
    return direction * (meanRadius / solidAngle);
}

std::vector<BallSector> equalVolumeSectors(int nShells, int nRings, int nAzimuthal)
{
    if (nShells < 1 || nRings < 1 || nAzimuthal < 1)
    {
        throw InputError("equalVolumeSectors: nShells, nRings and nAzimuthal must be >= 1, got "
                         + std::to_string(nShells) + ", " + std::to_string(nRings) + ", "
                         + std::to_string(nAzimuthal));
    }
    std::vector<BallSector> sectors;
    for (int k = 0; k < nShells; ++k)
    {
        // Equal-volume shells: r^3 steps evenly from 0 to 1.
        const double rIn = std::cbrt(double(k) / nShells);
        const double rOut = k + 1 == nShells ? 1.0 : std::cbrt(double(k + 1) / nShells);
        const double offset = (k % 2 == 1) ? pi / nAzimuthal : 0.0;
        addShell(sectors, rIn, rOut, nRings, nAzimuthal, offset);
    }
    return sectors;
}

} // namespace spoutlab
