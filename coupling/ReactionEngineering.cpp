#include "ReactionEngineering.hpp"

#include <algorithm>
#include <cmath>

namespace spoutlab
{

// selected by "dryingModel reactionEngineering;"
const Registration<DryingModel, ReactionEngineering> registeredReactionEngineering("reactionEngineering");

ReactionEngineering::ReactionEngineering(const Parameters& props)
    : DryingModel(isothermOf(props)), a_(props.getScalar("a")), b_(props.getScalar("b")),
      c_(props.getScalar("c"))
{
    if (!(a_ > 0.0)) throw props.badValue("a", "a relative activation energy at X_eq > 0");
    if (!(b_ >= 0.0)) throw props.badValue("b", "a number >= 0");
    if (!(c_ > 0.0)) throw props.badValue("c", "an exponent > 0");
}

double ReactionEngineering::relativeActivationEnergy(double moisture, double equilibriumMoisture) const
{
    const double x = std::max(0.0, moisture - equilibriumMoisture);
    return a_ * std::exp(-b_ * std::pow(x, c_));
}

namespace
{

ReactionEngineering::Surroundings surroundings(const SorptionIsotherm& isotherm, const Kernel& kernel,
                                               const MoistAir& air, double massTransferCoefficient)
{
    ReactionEngineering::Surroundings s;
    s.relativeHumidity = relativeHumidity(air);
    s.equilibriumMoisture = isotherm.equilibriumMoisture(s.relativeHumidity, air.temperature);
    s.temperatureRatio = air.temperature / kernel.temperature;
    s.saturatedVapour = saturationVapourDensity(kernel.temperature);
    s.farVapour = vapourDensity(air);
    s.conductance = massTransferCoefficient * surfaceArea(kernel);
    return s;
}

} // namespace

double ReactionEngineering::filmRate(const Surroundings& s, double moisture) const
{
    const double f = relativeActivationEnergy(moisture, s.equilibriumMoisture);
    // exp(-f dE_v,inf/(R T_p)) = RH_g^(f T_g/T_p)
    const double surface = std::pow(s.relativeHumidity, f * s.temperatureRatio) * s.saturatedVapour;
    return s.conductance * (surface - s.farVapour);
}

double ReactionEngineering::rate(const Kernel& kernel, double moisture, const double*, const MoistAir& air,
                                 double massTransferCoefficient) const
{
    const double mdot = filmRate(surroundings(isotherm(), kernel, air, massTransferCoefficient), moisture);
    return mdot > 0.0 && !(moisture > 0.0) ? 0.0 : mdot;
}

double ReactionEngineering::implicitStep(const Surroundings& s, double moisture, double perMass) const
{
    // Y = X - dt m_dot(Y)/m_d. The rate does not fall as Y rises, so the
    // residual Y - X + dt m_dot(Y)/m_d rises and has one root, between X and
    // the explicit step.
    auto residual = [&](double y) { return y - moisture + perMass * filmRate(s, y); };
    const double explicitStep = moisture - perMass * filmRate(s, moisture);
    const double lo = std::max(0.0, std::min(moisture, explicitStep)), hi = std::max(moisture, explicitStep);
    if (residual(lo) >= 0.0) return lo; // the step empties the kernel, or nothing moves
    // Newton with a central-difference slope: f' is infinite at X_eq when
    // c < 1, the residual's slope 1 + dt m_dot'/m_d is at least 1.
    auto slope = [&](double y) {
        const double h = 1e-7 * (1.0 + std::fabs(y));
        return std::max(1.0, (residual(y + h) - residual(y - h)) / (2.0 * h));
    };
    return increasingRoot(residual, slope, lo, hi, explicitStep);
}

double ReactionEngineering::advance(const Kernel& kernel, double& moisture, double*, const MoistAir& air,
                                    double massTransferCoefficient, double dt) const
{
    checkStep(moisture, massTransferCoefficient, dt);
    const Surroundings s = surroundings(isotherm(), kernel, air, massTransferCoefficient);
    const double old = moisture;
    // Sub-steps short against the kernel's drying time constant, measured by
    // the secant of the rate over an explicit step: dt m_dot'/m_d <= 0.02
    // per sub-step keeps backward Euler's error near 1 % of the change, at
    // most 1000 sub-steps (a longer step stays stable, only less accurate).
    const double perMass = dt / kernel.dryMass;
    const double explicitStep = old - perMass * filmRate(s, old);
    const double change = std::fabs(old - explicitStep);
    const double stiffness =
        change > 0.0
            ? perMass * std::fabs(filmRate(s, old) - filmRate(s, std::max(0.0, explicitStep))) / change
            : 0.0;
    const long steps = std::min(1000L, std::max(1L, static_cast<long>(std::ceil(stiffness / 0.02))));
    for (long k = 0; k < steps; ++k) moisture = implicitStep(s, moisture, perMass / steps);
    return kernel.dryMass * (old - moisture);
}

} // namespace spoutlab
