// Compiles core/pch/stages.h once; the stage libraries reuse the result.
