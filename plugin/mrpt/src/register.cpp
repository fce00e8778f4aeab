// Everything MRPT must know about, registered when the library is loaded
// (rawlog-grabber -p, rawlog-edit -p, RawLogViewer -l, LD_PRELOAD).
#include "omnirange/mrpt/OmniRangefinderSensor.h"

#include <mrpt/core/initializer.h>

MRPT_INITIALIZER(omnirange_register) { omnirange::COmniRangefinderSensor::doRegister(); }
