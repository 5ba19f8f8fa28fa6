#pragma once

#include "FMISimulation.h"


FMIStatus FMI2MESimulate(const FMISimulationSettings* s);
