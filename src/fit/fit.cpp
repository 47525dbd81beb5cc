#include "fit/fit.h"

#include <ceres/ceres.h>
