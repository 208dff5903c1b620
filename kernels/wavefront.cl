/* wavefront.cl — the program: every stage kernel, built together once.
 *
 *   generate → intersect → shade → intersect_shadow → roulette → accumulate
 *
 * Each stage reads one queue of path slots and appends to others
 * (include/wavefront/path_state.h); host/integrator/wavefront_scheduler.cpp launches them. */
#include "stages/generate.cl"
#include "stages/intersect.cl"
#include "stages/sort_by_material.cl"
#include "stages/shade.cl"
#include "stages/intersect_shadow.cl"
#include "stages/roulette.cl"
#include "stages/accumulate.cl"
