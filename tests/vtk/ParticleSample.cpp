#include "ParticleSample.hpp"

namespace spoutlab::sample
{

std::vector<Particle> particles()
{
    std::vector<Particle> p(count);
    for (std::size_t i = 0; i < count; ++i) p[i] = particle(i);
    return p;
}

// fluidForce for every particle; dragForce for none (a rank that sent no
// rows): the file must carry zeros, not garbage
std::vector<std::pair<std::string, std::vector<Vec3>>> vectors()
{
    std::vector<Vec3> f(count);
    for (std::size_t i = 0; i < count; ++i) f[i] = fluidForce(i);
    return {{"fluidForce", f}, {"dragForce", {}}};
}

std::vector<std::pair<std::string, std::vector<double>>> scalars()
{
    std::vector<double> T(count);
    for (std::size_t i = 0; i < count; ++i) T[i] = temperature(i);
    return {{"temperature", T}};
}

} // namespace spoutlab::sample
