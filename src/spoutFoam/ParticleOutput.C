/*---------------------------------------------------------------------------*\
    SpoutLab: the particle files of a coupled run.
\*---------------------------------------------------------------------------*/
#include "ParticleOutput.H"

#include "RankGather.H"

#include <algorithm>
#include <numeric>

namespace spoutlab
{

ParticleOutput::ParticleOutput(const std::string& directory)
:
    vtk_(directory, "particles")
{}


namespace
{

//- One row per particle: id, x (3), v (3), radius, the vectors (3 each),
//  the scalars
std::vector<double> packedRows
(
    const std::vector<Particle>& particles,
    const ParticleColumns& columns,
    std::size_t width
)
{
    std::vector<double> rows;
    rows.reserve(particles.size()*width);
    for (std::size_t i = 0; i < particles.size(); ++i)
    {
        const Particle& p = particles[i];
        rows.insert
        (
            rows.end(),
            {double(p.id), p.x.x, p.x.y, p.x.z, p.v.x, p.v.y, p.v.z, p.radius}
        );
        for (const auto& column : columns.vectors)
        {
            const Vec3& v = (*column.second)[i];
            rows.insert(rows.end(), {v.x, v.y, v.z});
        }
        for (const auto& column : columns.scalars)
        {
            rows.push_back((*column.second)[i]);
        }
    }
    return rows;
}

} // namespace


void ParticleOutput::write
(
    double time,
    const std::string& timeName,
    const std::vector<Particle>& particles,
    const ParticleColumns& columns
) const
{
    const std::size_t nv = columns.vectors.size(), ns = columns.scalars.size();
    const std::size_t width = 8 + 3*nv + ns;
    const std::vector<double> rows =
        gathered(packedRows(particles, columns, width), MPI_COMM_WORLD, false);
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    if (rank != 0) return;

    const std::size_t n = rows.size()/width;
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::sort
    (
        order.begin(), order.end(),
        [&](std::size_t a, std::size_t b) { return rows[a*width] < rows[b*width]; }
    );
    std::vector<Particle> all(n);
    std::vector<std::pair<std::string, std::vector<Vec3>>> vectors;
    for (const auto& column : columns.vectors) vectors.push_back({column.first, {}});
    std::vector<std::pair<std::string, std::vector<double>>> scalars;
    for (const auto& column : columns.scalars) scalars.push_back({column.first, {}});
    for (std::size_t k = 0; k < n; ++k)
    {
        const double* r = &rows[order[k]*width];
        all[k].id = long(r[0]);
        all[k].x = Vec3{r[1], r[2], r[3]};
        all[k].v = Vec3{r[4], r[5], r[6]};
        all[k].radius = r[7];
        r += 8;
        for (auto& column : vectors)
        {
            column.second.push_back(Vec3{r[0], r[1], r[2]});
            r += 3;
        }
        for (auto& column : scalars) column.second.push_back(*r++);
    }
    vtk_.write(time, timeName, all, vectors, scalars);
}

} // namespace spoutlab
