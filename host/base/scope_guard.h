// Scope guards: how host code releases what it made, once, whichever way a scope is left.
// A createX declares its result, guards it with its own destroyX and fills it step by
// step: a step that throws leaves the result released (destroyX is harmless on a partly
// made one), one that returns keeps it. The release runs in a destructor, so it must not
// throw; destroyX functions never do.
#pragma once

#include <exception>
#include <utility>

// Runs release when the scope ends, by return or by exception (teardown of a whole run).
template <typename Release> class [[nodiscard]] ScopeExit {
  public:
    explicit ScopeExit(Release release) : release_(std::move(release)) {}
    ~ScopeExit() { release_(); }
    ScopeExit(const ScopeExit&) = delete;
    ScopeExit& operator=(const ScopeExit&) = delete;

  private:
    Release release_;
};

// Runs release only when an exception leaves the scope (a createX's partial result).
template <typename Release> class [[nodiscard]] OnFailure {
  public:
    explicit OnFailure(Release release)
        : release_(std::move(release)), exceptionsAtStart_(std::uncaught_exceptions()) {}
    ~OnFailure() {
        if (std::uncaught_exceptions() > exceptionsAtStart_) release_();
    }
    OnFailure(const OnFailure&) = delete;
    OnFailure& operator=(const OnFailure&) = delete;

  private:
    Release release_;
    int exceptionsAtStart_;
};
