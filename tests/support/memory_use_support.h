// A part of a MemoryUse (pipeline/memory_use.h) by name, for the memory tests of several suites.
#pragma once

#include "pipeline/memory_use.h"

#include <gtest/gtest.h>

#include <string>

namespace vplab::test {

/// The bytes of the part named `name`; a test failure (and 0) when there is none.
inline size_t bytesOf(const MemoryUse& use, const std::string& name) {
  for (const MemoryPart& p : use)
    if (p.name == name) return p.bytes;
  ADD_FAILURE() << "no part named " << name;
  return 0;
}

}  // namespace vplab::test
