#pragma once

#include "FMISimulation.h"


FMIStatus FMI1CSSimulate(const FMISimulationSettings* s);
