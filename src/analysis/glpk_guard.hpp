#pragma once
// GLPK's problem object, its terminal output, and a guard around its calls. GLPK reports an
// internal error (an invalid scale factor, a basis it cannot factorize) by calling its error hook
// and then aborting the process, unless the hook leaves by longjmp; GLPK's environment is then in
// an undefined state and must be freed (glp_free_env, which frees every problem object of the
// thread). glpk_guarded turns such an error into a std::runtime_error, so no input can abort the
// program (docs/limit_analysis.md).
//
// Only GLPK calls go inside glpk_guarded: the jump skips every frame between it and GLPK, so no
// C++ object with a destructor may live there. One GlpkProblem at a time per thread: the error
// frees them all.
#include <csetjmp>
#include <stdexcept>

#include <glpk.h>

namespace blockdem {

/// GLPK's scaling and basis routines print to the terminal whatever the solver's message level:
/// its terminal output is off while a problem is solved, and restored after (the physics never
/// prints).
struct GlpkSilence {
    int previous = glp_term_out(GLP_OFF);
    GlpkSilence() = default;
    GlpkSilence(const GlpkSilence&) = delete;
    GlpkSilence& operator=(const GlpkSilence&) = delete;
    ~GlpkSilence() { glp_term_out(previous); }
};

struct GlpkProblem {
    glp_prob* lp = glp_create_prob();  ///< null once an error has freed GLPK's environment
    GlpkProblem() = default;
    GlpkProblem(const GlpkProblem&) = delete;
    GlpkProblem& operator=(const GlpkProblem&) = delete;
    ~GlpkProblem() {
        if (lp) glp_delete_prob(lp);
    }
};

namespace detail {
struct GlpkJump {
    std::jmp_buf buffer;
};
inline void jump_out_of_glpk(void* info) { std::longjmp(static_cast<GlpkJump*>(info)->buffer, 1); }
}  // namespace detail

/// Runs call() (GLPK calls on problem.lp only). If GLPK stops on an internal error, frees its
/// environment, marks problem as gone and throws std::runtime_error; otherwise returns normally.
template <class Call>
void glpk_guarded(GlpkProblem& problem, Call&& call) {
    detail::GlpkJump jump;
    glp_error_hook(detail::jump_out_of_glpk, &jump);
    if (setjmp(jump.buffer) == 0) {
        call();
        glp_error_hook(nullptr, nullptr);
        return;
    }
    glp_error_hook(nullptr, nullptr);
    problem.lp = nullptr;
    glp_free_env();
    throw std::runtime_error("the LP solver (GLPK) stopped on an internal error (its message is above); no result");
}

}  // namespace blockdem
