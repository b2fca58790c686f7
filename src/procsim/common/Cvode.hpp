#pragma once
// The SUNDIALS objects of one CVODE integration, freed together however the
// integration ends, and the check of CVODE's return flags.  Header-only: a
// model that integrates with CVODE links SUNDIALS itself.
#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <stdexcept>
#include <string>

namespace procsim
{

struct CvodeSession
{
    SUNContext ctx = nullptr;
    N_Vector y = nullptr;
    N_Vector atol = nullptr; // per-component absolute tolerances, if used
    SUNMatrix A = nullptr;
    SUNLinearSolver LS = nullptr;
    void* mem = nullptr;

    CvodeSession() = default;
    CvodeSession(const CvodeSession&) = delete;
    CvodeSession& operator=(const CvodeSession&) = delete;
    ~CvodeSession()
    {
        if (mem) CVodeFree(&mem);
        if (LS) SUNLinSolFree(LS);
        if (A) SUNMatDestroy(A);
        if (y) N_VDestroy(y);
        if (atol) N_VDestroy(atol);
        if (ctx) SUNContext_Free(&ctx);
    }
};

// A negative flag is a failure: std::runtime_error naming the call.
inline void checkCvode(int flag, const char* what)
{
    if (flag < 0)
    {
        throw std::runtime_error(std::string("CVODE failed in ") + what + " (flag " + std::to_string(flag)
                                 + ")");
    }
}

} // namespace procsim
