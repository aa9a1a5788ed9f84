/* rt_version.h - the library's version (the host tools print it too). */
#ifndef RT_VERSION_H
#define RT_VERSION_H

#define RT_VERSION_MAJOR 0
#define RT_VERSION_MINOR 9
#define RT_VERSION_PATCH 0
#define RT_VERSION_STRING "0.9.0"

#endif
