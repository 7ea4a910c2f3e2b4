#include "core/stepper.h"
