// cpp-httplib, as every file of server/ includes it. Its header pulls in <resolv.h>, whose
// `_res` macro breaks Eigen's headers (core/) when they come later in the same file; nothing
// here uses the resolver's state, so the macro goes.
#pragma once

#include <httplib.h>
#undef _res
