#pragma once
// Boost.Geometry for the material model, included in one place so that Boost 1.74's noise stays out
// of our builds: the deprecated-header notes it triggers itself, and GCC 12's -Wmaybe-uninitialized
// false positives inside its envelope code (the diagnostic state is taken at the header's lines).
#ifndef BOOST_ALLOW_DEPRECATED_HEADERS
#define BOOST_ALLOW_DEPRECATED_HEADERS
#endif
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>
#pragma GCC diagnostic pop
#else
#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>
#endif
