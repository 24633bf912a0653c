#pragma once
// Each harness feeds arbitrary bytes to one reader. The reader may refuse the
// input with its own error type (that is the contract: one clear line, exit 2);
// anything else — a crash, a sanitizer report, another exception, a hang — is
// a bug. Built as libFuzzer targets with clang (scripts/fuzz) and, with
// replay_main.cpp, as ordinary tests that replay the saved corpus.
#include <cstddef>
#include <cstdint>
#include <string_view>

#define ACO_FUZZ_INPUT(data, size) std::string_view(reinterpret_cast<const char*>(data), size)
