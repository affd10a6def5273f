// Compiles proto/pch/service.h once; the service libraries reuse the result.
