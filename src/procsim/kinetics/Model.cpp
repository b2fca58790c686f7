#include "kinetics/Model.hpp"

#include <cmath>

namespace procsim::kinetics
{

Model::Model(const Case& c) : case_(c)
{
    const std::size_t n = c.mech.species.size();
    stateOf_.assign(n, -1);
    fixed_.assign(n, 0.0);
    const bool radicalFixed = c.radicalFixed();
    const std::size_t rad = c.mech.hasRadical() ? c.mech.radicalIndex() : n;
    for (std::size_t i = 0; i < n; ++i)
    {
        if (radicalFixed && i == rad)
        {
            fixed_[i] = c.radicalConcentration();
            continue;
        }
        stateOf_[i] = static_cast<long>(stateSpecies_.size());
        stateSpecies_.push_back(i);
    }
    const auto f = c.feedRate();
    feed_ = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(stateSpecies_.size()));
    for (std::size_t s = 0; s < stateSpecies_.size(); ++s)
        feed_[static_cast<Eigen::Index>(s)] = f[stateSpecies_[s]];
}

Eigen::VectorXd Model::initialState() const
{
    Eigen::VectorXd y(static_cast<Eigen::Index>(size()));
    for (std::size_t s = 0; s < size(); ++s)
        y[static_cast<Eigen::Index>(s)] = case_.initial[stateSpecies_[s]];
    return y;
}

double Model::rate(const Reaction& r, const Eigen::VectorXd& y) const
{
    double v = r.k;
    for (const auto& t : r.reactants)
    {
        const long s = stateOf_[t.species];
        const double c = s < 0 ? fixed_[t.species] : y[s];
        v *= t.stoich == 1.0 ? c : std::pow(c, t.stoich);
    }
    return v;
}

void Model::rhs(const Eigen::VectorXd& y, Eigen::VectorXd& dydt) const
{
    dydt = feed_;
    for (const auto& r : case_.mech.reactions)
    {
        const double v = rate(r, y);
        if (v == 0.0) continue;
        for (const auto& t : r.reactants)
            if (stateOf_[t.species] >= 0) dydt[stateOf_[t.species]] -= t.stoich * v;
        for (const auto& t : r.products)
            if (stateOf_[t.species] >= 0) dydt[stateOf_[t.species]] += t.stoich * v;
    }
}

void Model::jacobian(const Eigen::VectorXd& y, Eigen::MatrixXd& jac) const
{
    const auto n = static_cast<Eigen::Index>(size());
    jac = Eigen::MatrixXd::Zero(n, n);
    for (const auto& r : case_.mech.reactions)
    {
        // d rate / d y_j for each integrated reactant j
        for (std::size_t a = 0; a < r.reactants.size(); ++a)
        {
            const long j = stateOf_[r.reactants[a].species];
            if (j < 0) continue;
            double d = r.k;
            for (std::size_t b = 0; b < r.reactants.size(); ++b)
            {
                const auto& t = r.reactants[b];
                const long s = stateOf_[t.species];
                const double c = s < 0 ? fixed_[t.species] : y[s];
                if (b == a)
                    d *= t.stoich * (t.stoich == 1.0 ? 1.0 : std::pow(c, t.stoich - 1.0));
                else
                    d *= t.stoich == 1.0 ? c : std::pow(c, t.stoich);
            }
            for (const auto& t : r.reactants)
                if (stateOf_[t.species] >= 0) jac(stateOf_[t.species], j) -= t.stoich * d;
            for (const auto& t : r.products)
                if (stateOf_[t.species] >= 0) jac(stateOf_[t.species], j) += t.stoich * d;
        }
    }
}

bool Model::isLinear() const
{
    for (const auto& r : case_.mech.reactions)
    {
        double order = 0;
        for (const auto& t : r.reactants)
            if (stateOf_[t.species] >= 0) order += t.stoich;
        if (order > 1.0) return false;
    }
    return true;
}

void Model::linearForm(Eigen::MatrixXd& a, Eigen::VectorXd& b) const
{
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(size()));
    jacobian(zero, a); // exact for a linear system: rates are k * fixed * y_j
    rhs(zero, b);      // feed plus zero-order production
}

Eigen::VectorXd Model::allSpecies(const Eigen::VectorXd& y) const
{
    Eigen::VectorXd c(static_cast<Eigen::Index>(fixed_.size()));
    for (std::size_t i = 0; i < fixed_.size(); ++i)
        c[static_cast<Eigen::Index>(i)] = stateOf_[i] < 0 ? fixed_[i] : y[stateOf_[i]];
    return c;
}

} // namespace procsim::kinetics
