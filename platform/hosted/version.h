/* version.h - the one version string of the hosted tools (rt, rt-scenec). */
#ifndef RT_VERSION_H
#define RT_VERSION_H

#define RT_VERSION "0.9.0"

#endif
