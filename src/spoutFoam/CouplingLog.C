/*---------------------------------------------------------------------------*\
    SpoutLab: postProcessing/coupling.csv.
\*---------------------------------------------------------------------------*/
#include "CouplingLog.H"

#include "fvCFD.H"

#include <cstdio>
#include <cstdlib>
#include <iomanip>

namespace spoutlab
{

namespace
{

// Keep the header and every row up to tMax (the restart time, or just
// before it when the restart recomputes that row).
void trimRowsAfter(const std::string& file, double tMax)
{
    std::ifstream in(file);
    if (!in) return;
    std::string kept, line;
    while (std::getline(in, line))
    {
        char* end = nullptr;
        const double t = std::strtod(line.c_str(), &end);
        if (end == line.c_str() || t <= tMax) kept += line + '\n';
    }
    in.close();
    const std::string tmp = file + ".tmp";
    std::ofstream(tmp, std::ios::trunc) << kept;
    std::rename(tmp.c_str(), file.c_str());
}

} // namespace


CouplingLog::CouplingLog
(
    const Foam::Time& runTime, bool heat, bool moisture, bool resumed
)
{
    if (!Foam::Pstream::master()) return;
    const Foam::fileName dir = runTime.globalPath()/"postProcessing";
    Foam::mkDir(dir);
    const std::string file = dir/"coupling.csv";
    const bool fresh = runTime.value() == 0;
    if (!fresh)
    {
        const double stepsPast = resumed ? 0.5 : -0.5;
        trimRowsAfter(file, runTime.value() + stepsPast*runTime.deltaTValue());
    }
    file_.reset
    (
        new std::ofstream(file, fresh ? std::ios::trunc : std::ios::app)
    );
    if (fresh || file_->tellp() == 0) writeHeader(heat, moisture);
}


void CouplingLog::writeHeader(bool heat, bool moisture)
{
    *file_
        << "time [s],particles,particle mass [kg],solid volume [m3],"
        << "min voidfraction,"
        << "particle drag x [N],particle drag y [N],particle drag z [N],"
        << "gas exchange x [N],gas exchange y [N],gas exchange z [N],"
        << "gas received x [N],gas received y [N],gas received z [N]";
    if (heat)
    {
        *file_
            << ",heat to particles [W],heat from gas [W],"
            << "gas enthalpy in [W],gas enthalpy out [W],"
            << "gas outlet temperature [K],gas energy [J],"
            << "particle energy [J],mean particle temperature [K]";
    }
    if (moisture)
    {
        *file_
            << ",particle water [kg],water lost by particles [kg/s],"
            << "vapour to gas [kg/s],vapour in [kg/s],vapour out [kg/s],"
            << "gas vapour [kg],outlet humidity ratio,outlet relative humidity,"
            << "latent heat from particles [W],sorption heat [W],"
            << "vapour enthalpy to gas [W],gas latent energy [J],"
            << "latent energy in [W],latent energy out [W]";
    }
    *file_ << '\n';
}


void CouplingLog::write(const CouplingRow& row)
{
    if (!file_) return;
    std::ostream& os = *file_;
    os << std::setprecision(10) << row.time << ',' << row.particles << ','
        << row.particleMass << ',' << row.solidVolume << ','
        << row.minVoidFraction;
    for (const Vec3* v : {&row.particleDrag, &row.gasExchange, &row.gasReceived})
    {
        os << ',' << v->x << ',' << v->y << ',' << v->z;
    }
    if (row.heat)
    {
        // energies of order 1e6 J change by a few J per step: 15 digits
        // keep the step-by-step balance readable from the file
        const HeatRow& h = *row.heat;
        os << std::setprecision(15) << ',' << h.toParticles << ',' << h.gasGave
            << ',' << h.inflow << ',' << h.outflow << ','
            << h.outletTemperature << ',' << h.gasEnergy << ','
            << h.particleEnergy << ',' << h.meanParticleTemperature;
    }
    if (row.moisture)
    {
        const MoistureRow& m = *row.moisture;
        os << std::setprecision(15);
        for
        (
            const double v
          : {
                m.particleWater, m.waterLost, m.vapourReceived, m.vapourIn,
                m.vapourOut, m.gasVapour, m.outletHumidity, m.outletRH,
                m.latentHeat, m.sorptionHeat, m.vapourEnthalpy,
                m.gasLatentEnergy, m.latentIn, m.latentOut
            }
        )
        {
            os << ',' << v;
        }
    }
    os << '\n';
    os.flush();
}


void CouplingLog::flush()
{
    if (file_) file_->flush();
}

} // namespace spoutlab
