#pragma once
// Every Fresnel model's kernel and unit (models/), the registry that lists them, and the media
// variants: one include for code that uses the kernels directly.
#include "fresnel/media.h"
#include "fresnel/model_set.h"
#include "fresnel/registry.h"
