// uses low/, as its row allows
#pragma once
#include "low/a.h"
