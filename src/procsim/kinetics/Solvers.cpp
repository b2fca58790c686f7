#include "common/Cvode.hpp"
#include "kinetics/Solvers.hpp"

#include <cmath>
#include <map>
#include <stdexcept>
#include <unsupported/Eigen/MatrixFunctions>

#include "common/Checked.hpp"
#include "common/Csv.hpp"

namespace procsim::kinetics
{

std::vector<double> outputTimes(double duration, double interval)
{
    std::vector<double> t;
    const long n = static_cast<long>(std::floor(duration / interval + 1e-9));
    for (long i = 0; i <= n; ++i) t.push_back(i * interval);
    if (duration - t.back() > 1e-9 * duration) t.push_back(duration);
    return t;
}

Trajectory solve(const Model& model, const std::vector<double>& times, const SolverOptions& opt)
{
    if (opt.method == "expm")
    {
        if (!model.isLinear())
        {
            throw InputError(model.caseData().file
                             + ": key 'solver.method' expm needs a mechanism linear in the integrated species"
                               " (use cvode)");
        }
        return solveExpm(model, times);
    }
    if (opt.method == "rk4") return solveRk4(model, times, opt.rk4Step);
    if (opt.method == "cvode") return solveCvode(model, times, opt.rtol, opt.atol);
    throw InputError("unknown solver '" + opt.method + "' (expected expm, rk4 or cvode)");
}

Trajectory solveExpm(const Model& model, const std::vector<double>& times)
{
    const auto n = static_cast<Eigen::Index>(model.size());
    Eigen::MatrixXd a;
    Eigen::VectorXd b;
    model.linearForm(a, b);
    Eigen::MatrixXd aug = Eigen::MatrixXd::Zero(n + 1, n + 1);
    aug.topLeftCorner(n, n) = a;
    aug.topRightCorner(n, 1) = b;

    Trajectory tr;
    Eigen::VectorXd z(n + 1);
    z.head(n) = model.initialState();
    z[n] = 1.0;
    tr.t.push_back(times.front());
    tr.y.push_back(z.head(n));
    std::map<double, Eigen::MatrixXd> cache; // propagator per interval length
    for (std::size_t i = 1; i < times.size(); ++i)
    {
        const double dt = times[i] - times[i - 1];
        auto it = cache.find(dt);
        if (it == cache.end()) it = cache.emplace(dt, Eigen::MatrixXd((aug * dt).exp())).first;
        z = it->second * z;
        z[n] = 1.0;
        tr.t.push_back(times[i]);
        tr.y.push_back(z.head(n));
        ++tr.steps;
    }
    return tr;
}

Trajectory solveRk4(const Model& model, const std::vector<double>& times, double step)
{
    stepCount(times.back() - times.front(), step, 100000000L,
              model.caseData().file + ": key 'solver.rk4_step_s'",
              "rk4 with a step of " + formatNumber(step) + " s", "use a longer step or solver cvode");
    Trajectory tr;
    Eigen::VectorXd y = model.initialState();
    const auto n = y.size();
    Eigen::VectorXd k1(n), k2(n), k3(n), k4(n);
    tr.t.push_back(times.front());
    tr.y.push_back(y);
    for (std::size_t i = 1; i < times.size(); ++i)
    {
        const double span = times[i] - times[i - 1];
        const long m = std::max(1L, static_cast<long>(std::ceil(span / step - 1e-9)));
        const double h = span / static_cast<double>(m);
        for (long s = 0; s < m; ++s)
        {
            model.rhs(y, k1);
            model.rhs(y + 0.5 * h * k1, k2);
            model.rhs(y + 0.5 * h * k2, k3);
            model.rhs(y + h * k3, k4);
            y += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
        }
        tr.steps += m;
        tr.t.push_back(times[i]);
        tr.y.push_back(y);
    }
    return tr;
}

namespace
{

int cvRhs(sunrealtype, N_Vector y, N_Vector ydot, void* data)
{
    const auto* model = static_cast<const Model*>(data);
    const auto n = static_cast<Eigen::Index>(model->size());
    Eigen::Map<const Eigen::VectorXd> yv(N_VGetArrayPointer(y), n);
    Eigen::VectorXd d;
    model->rhs(yv, d);
    Eigen::Map<Eigen::VectorXd>(N_VGetArrayPointer(ydot), n) = d;
    return 0;
}

int cvJac(sunrealtype, N_Vector y, N_Vector, SUNMatrix jac, void* data, N_Vector, N_Vector, N_Vector)
{
    const auto* model = static_cast<const Model*>(data);
    const auto n = static_cast<Eigen::Index>(model->size());
    Eigen::Map<const Eigen::VectorXd> yv(N_VGetArrayPointer(y), n);
    Eigen::MatrixXd j;
    model->jacobian(yv, j);
    for (Eigen::Index c = 0; c < n; ++c)
    {
        sunrealtype* col = SUNDenseMatrix_Column(jac, c);
        for (Eigen::Index r = 0; r < n; ++r) col[r] = j(r, c);
    }
    return 0;
}

} // namespace

Trajectory solveCvode(const Model& model, const std::vector<double>& times, double rtol, double atol)
{
    const auto n = static_cast<sunindextype>(model.size());
    CvodeSession r;
    checkCvode(SUNContext_Create(nullptr, &r.ctx), "SUNContext_Create");
    r.y = N_VNew_Serial(n, r.ctx);
    const Eigen::VectorXd y0 = model.initialState();
    for (sunindextype i = 0; i < n; ++i) NV_Ith_S(r.y, i) = y0[i];
    r.mem = CVodeCreate(CV_BDF, r.ctx);
    if (!r.mem) throw std::runtime_error("CVodeCreate failed");
    CVodeSetErrFile(r.mem, nullptr); // failures are reported as one line by checkCvode
    checkCvode(CVodeInit(r.mem, cvRhs, times.front(), r.y), "CVodeInit");
    checkCvode(CVodeSStolerances(r.mem, rtol, atol), "CVodeSStolerances");
    checkCvode(CVodeSetUserData(r.mem, const_cast<Model*>(&model)), "CVodeSetUserData");
    r.A = SUNDenseMatrix(n, n, r.ctx);
    r.LS = SUNLinSol_Dense(r.y, r.A, r.ctx);
    checkCvode(CVodeSetLinearSolver(r.mem, r.LS, r.A), "CVodeSetLinearSolver");
    checkCvode(CVodeSetJacFn(r.mem, cvJac), "CVodeSetJacFn");
    checkCvode(CVodeSetMaxNumSteps(r.mem, 1000000), "CVodeSetMaxNumSteps");
    checkCvode(CVodeSetStopTime(r.mem, times.back()), "CVodeSetStopTime");

    Trajectory tr;
    tr.t.push_back(times.front());
    tr.y.push_back(y0);
    for (std::size_t i = 1; i < times.size(); ++i)
    {
        sunrealtype t = 0;
        checkCvode(CVode(r.mem, times[i], r.y, &t, CV_NORMAL), "CVode");
        Eigen::VectorXd y(n);
        for (sunindextype k = 0; k < n; ++k) y[k] = NV_Ith_S(r.y, k);
        tr.t.push_back(times[i]);
        tr.y.push_back(y);
    }
    long steps = 0;
    CVodeGetNumSteps(r.mem, &steps);
    tr.steps = steps;
    return tr;
}

} // namespace procsim::kinetics
