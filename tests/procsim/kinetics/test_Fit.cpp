// Fitting: data generated from known parameters plus noise must give back
// those parameters within their standard errors.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "TestUtil.hpp"
#include "kinetics/Fit.hpp"

using namespace procsim::kinetics;

TEST(KineticsFit, RecoversKnownParametersFromNoisyData)
{
    const CaseSource src = CaseSource::load(kt::casesDir() + "/base_0.3mA_30mgL_30ppm.yaml");
    // truth: the paper's k3, k12 and [OH] slope
    std::vector<FitParameter> truth = {
        {"k.k3", 5e9}, {"k.k12", 1e10}, {"oh.slope_mg_per_L_per_mA", 8.77e-10}};
    const double sigma = 0.2; // mg/L
    std::mt19937 rng(20240607);
    std::normal_distribution<double> noise(0.0, sigma);
    std::vector<FitDataset> data;
    for (double current : {0.1, 0.3, 0.5})
    {
        FitDataset d;
        d.name = std::to_string(current) + " mA";
        d.source = src;
        d.set = {{"corona.current_mA", current}};
        for (int h = 1; h <= 10; ++h) d.t.push_back(h * 3600.0);
        d.quantities = {"PH", "AA", "TOC"};
        d.sigma = sigma;
        d.measured = predict(d, truth, false);
        for (auto& q : d.measured)
            for (auto& v : q) v += noise(rng);
        data.push_back(d);
    }
    std::vector<FitParameter> start = {{"k.k3", 2.5e9}, {"k.k12", 2e10}, {"oh.slope_mg_per_L_per_mA", 5e-10}};
    FitOptions opt;
    opt.scaleByResidualVariance = false; // sigma is known exactly here
    const FitResult r = fitParameters(start, data, opt);
    ASSERT_TRUE(r.converged) << r.report;
    for (std::size_t i = 0; i < truth.size(); ++i)
    {
        const auto& p = r.parameters[i];
        EXPECT_GT(p.stdError, 0.0) << p.key;
        EXPECT_LT(p.stdError / p.estimate, 0.2) << p.key; // the data do determine it
        EXPECT_LT(std::fabs(p.estimate - truth[i].initial), 3.0 * p.stdError)
            << p.key << " estimate " << p.estimate << " +- " << p.stdError;
    }
    // residuals are the noise: chi2 per degree of freedom near 1
    const double dof = r.points - 3.0;
    EXPECT_NEAR(r.chi2 / dof, 1.0, 4.0 * std::sqrt(2.0 / dof));
    EXPECT_NEAR(r.rmse, sigma, 0.3 * sigma);
}
