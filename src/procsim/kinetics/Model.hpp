#pragma once
// The species balances built from the reaction list (mass action), with the
// pseudo-steady radical held at the [OH] model's value, and the liquid-phase
// feed of absorbed gas:  dc/dt = feed + sum_r nu_r k_r prod c^order.
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "kinetics/Case.hpp"

namespace procsim::kinetics
{

class Model
{
public:
    explicit Model(const Case& c);

    std::size_t size() const { return stateSpecies_.size(); }
    // mechanism species index of each state component
    const std::vector<std::size_t>& stateSpecies() const { return stateSpecies_; }
    const Case& caseData() const { return case_; }

    Eigen::VectorXd initialState() const;
    void rhs(const Eigen::VectorXd& y, Eigen::VectorXd& dydt) const;
    void jacobian(const Eigen::VectorXd& y, Eigen::MatrixXd& jac) const;

    // true if every reaction is at most first order in the integrated species
    // (the paper's case: OH pseudo-steady), so dy/dt = A y + b exactly
    bool isLinear() const;
    void linearForm(Eigen::MatrixXd& a, Eigen::VectorXd& b) const;

    // concentrations of all mechanism species (mol/L), radical included
    Eigen::VectorXd allSpecies(const Eigen::VectorXd& y) const;

private:
    Case case_;
    std::vector<std::size_t> stateSpecies_;
    std::vector<long> stateOf_; // species -> state index or -1 (fixed)
    std::vector<double> fixed_; // species -> fixed concentration (mol/L)
    Eigen::VectorXd feed_;      // per state, mol/(L s)

    double rate(const Reaction& r, const Eigen::VectorXd& y) const;
};

} // namespace procsim::kinetics
