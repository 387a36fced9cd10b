#pragma once
// The message of the shadowlab::Error that `f` throws, for tests that check it.
#include <shadowlab/Error.h>

#include <functional>
#include <string>

inline std::string errorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const shadowlab::Error& e) {
        return e.what();
    }
    return "<no shadowlab::Error thrown>";
}
