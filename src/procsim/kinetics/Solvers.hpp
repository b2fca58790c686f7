#pragma once
// Three ways to integrate the species balances:
//  expm  - exact solution of dy/dt = A y + b (linear, constant coefficients)
//          by the matrix exponential of the augmented matrix [A b; 0 0];
//  rk4   - classic fourth-order Runge-Kutta with a fixed step (the paper's method);
//  cvode - SUNDIALS CVODE, variable-order BDF with the analytic Jacobian, for
//          stiff and nonlinear mechanisms.
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "kinetics/Case.hpp"
#include "kinetics/Model.hpp"

namespace procsim::kinetics
{

struct Trajectory
{
    std::vector<double> t;          // s
    std::vector<Eigen::VectorXd> y; // state at each t (mol/L)
    long steps = 0;                 // integrator steps taken
};

// times must start at 0 and increase
Trajectory solve(const Model& model, const std::vector<double>& times, const SolverOptions& opt);

Trajectory solveExpm(const Model& model, const std::vector<double>& times);
Trajectory solveRk4(const Model& model, const std::vector<double>& times, double step);
Trajectory solveCvode(const Model& model, const std::vector<double>& times, double rtol, double atol);

// 0, dt, 2 dt, ... up to and including `duration` (the last interval may be shorter)
std::vector<double> outputTimes(double duration, double interval);

} // namespace procsim::kinetics
