#pragma once
// Batch energy metrics of the tray-dryer paper (Table 1):
//   X   = kg water / kg bone-dry material (dry basis)
//   eta = energy used for evaporating water / energy used for operating dryer
//   E   = energy used for operating dryer / mass of evaporated water
#include <optional>
#include <string>
#include <vector>

namespace procsim::dryer
{

// How "energy used for evaporating water" is counted per kg of water.
struct LatentHeatConvention
{
    enum class Kind
    {
        // Water enters as liquid at ambient temperature and leaves as vapour
        // at the hot-air temperature: h_v(T_hot) - h_l(T_amb)
        //   = 2501 + 1.86 T_hot - 4.186 T_amb  [kJ/kg]  (ASHRAE ideal-gas datum).
        AmbientLiquidToHotAirVapour,
        // A fixed value per kg, e.g. 2501 kJ/kg (vaporisation at 0 degC).
        Constant,
    };
    Kind kind = Kind::AmbientLiquidToHotAirVapour;
    double constant = 2501.0e3; // J/kg, for Kind::Constant

    double perKg(double hotAirC, double ambientC) const; // J/kg
    std::string describe() const;
};

struct BatchRecord
{
    std::string id;
    std::string dryer; // free text, e.g. "old" / "modified"
    std::string material;
    double hotAirC = 0;               // hot-air set-point, degC
    double ambientC = 0;              // ambient temperature, degC
    double x1 = 0;                    // initial average moisture, kg/kg dry basis
    double x2 = 0;                    // final average moisture, kg/kg dry basis
    double timeS = 0;                 // drying time, s
    double electricityJ = 0;          // electricity for the batch, J
    std::optional<double> rateKgPerS; // average evaporation rate
    std::optional<double> dryMassKg;
    std::optional<double> waterKg; // evaporated water, if weighed directly
    // Published values to compare with (optional).
    std::optional<double> paperEta; // fraction
    std::optional<double> paperE;   // J/kg
    std::string source;             // file (for messages)
};

struct BatchMetrics
{
    std::string id;
    double waterKg = 0;    // evaporated water
    std::string waterFrom; // "evaporated_water", "dry_mass", "rate x time"
    double dryMassKg = 0;
    double rateKgPerH = 0; // water / drying time
    double electricityKWh = 0;
    double latentJPerKg = 0;
    double eta = 0;            // fraction
    double specificEnergy = 0; // J/kg water
    // Cross-check: water implied by a reported rate x time, when the water
    // came from another source (NaN if not applicable).
    double rateWaterKg = 0;
    bool rateDisagrees = false; // > 1 % apart
};

BatchMetrics computeMetrics(const BatchRecord& b, const LatentHeatConvention& lh);

// Records from YAML (key 'batches': list) or CSV (one row per batch).
struct BatchFile
{
    std::vector<BatchRecord> batches;
    LatentHeatConvention latentHeat;
};
BatchFile readBatchFile(const std::string& path);

// Validates one record; throws InputError naming file and key.
void validate(const BatchRecord& b, const std::string& where);

// "11:50" -> seconds; throws std::invalid_argument on bad text.
double parseHoursMinutes(const std::string& text);

} // namespace procsim::dryer
