// The one header a law file includes.
#pragma once

#include "pdgen/expr.hpp"
#include "pdgen/law.hpp"
#include "pdgen/tensor.hpp"
