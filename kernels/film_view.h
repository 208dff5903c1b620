/* film_view.h — the film's buffers (include/wavefront/film_buffers.h) gathered into
 * one FilmBuffers, which accumulation and the bounce layers take as one
 * argument. Device only. */
#ifndef WF_KERNEL_FILM_H
#define WF_KERNEL_FILM_H

#include "wavefront/compat.h"
#include "wavefront/film_buffers.h"

#define WF_FILM_MEMBER(type, name, extent, what) __global type* name;
typedef struct FilmBuffers {
    WF_FILM_BUFFERS(WF_FILM_MEMBER)
} FilmBuffers;
#undef WF_FILM_MEMBER

#endif
