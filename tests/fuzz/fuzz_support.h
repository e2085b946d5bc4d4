#pragma once
// What every fuzz target checks: the reader returns, or throws its own error type. Any other
// exception is a finding, reported on stderr and turned into an abort so libFuzzer keeps the input.
#include <cxxabi.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>
#include <string>
#include <string_view>
#include <typeinfo>

namespace raystep::fuzz {

inline std::string_view asText(const std::uint8_t* data, std::size_t size) {
    return {reinterpret_cast<const char*>(data), size};
}

[[noreturn]] inline void finding(const char* what, const std::string& detail) {
    std::fprintf(stderr, "raystep fuzz finding: %s: %s\n", what, detail.c_str());
    std::fflush(stderr);
    std::abort();
}

inline std::string typeName(const std::type_info& t) {
    int status = 0;
    const std::unique_ptr<char, decltype(&std::free)> name(
        abi::__cxa_demangle(t.name(), nullptr, nullptr, &status), &std::free);
    return status == 0 && name ? name.get() : t.name();
}

/// Runs `fn`; an exception other than `Allowed` is a finding of `reader`.
template <typename Allowed, typename Fn>
void expectOwnErrorOnly(const char* reader, Fn&& fn) {
    try {
        fn();
    } catch (const Allowed&) {
    } catch (const std::exception& e) {
        finding(reader, "threw " + typeName(typeid(e)) + " (not its own error type): " + e.what());
    } catch (...) {
        finding(reader, "threw something that is not a std::exception");
    }
}

}  // namespace raystep::fuzz
