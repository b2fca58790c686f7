#pragma once
// A particle frame whose every value is a formula of the particle's index,
// so a reader can be checked against the formula instead of the writer.
// tests/python/test_vtkreader.py writes the same formulas again.
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "Particle.hpp"

namespace spoutlab::sample
{

// 5000 particles: every array spans several 32 KiB compression blocks
constexpr std::size_t count = 5000;

inline Particle particle(std::size_t i)
{
    const double s = static_cast<double>(i);
    Particle p;
    p.id = 7 + 3 * static_cast<long>(i);
    p.x = {-0.2 + 8e-5 * s, 0.01 + 1e-6 * s, 0.3 * std::sin(s)};
    p.v = {std::cos(s), std::sin(s), 0.1 * s / count};
    p.radius = 0.004 + 1e-7 * static_cast<double>(i % 5);
    return p;
}

inline Vec3 fluidForce(std::size_t i)
{
    return {1e-4 * std::sin(0.5 * i), -2e-5, 3e-4 * std::cos(0.5 * i)};
}
inline double temperature(std::size_t i)
{
    return 293.15 + 60.0 * i / count;
}

std::vector<Particle> particles();
std::vector<std::pair<std::string, std::vector<Vec3>>> vectors();
std::vector<std::pair<std::string, std::vector<double>>> scalars();

} // namespace spoutlab::sample
