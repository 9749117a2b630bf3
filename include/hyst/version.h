/* SPDX-License-Identifier: MIT */
/**
 * @file version.h
 * @brief The version of hyst: the one place it is defined (CMake reads it).
 */
#ifndef HYST_VERSION_H
#define HYST_VERSION_H

#define HYST_VERSION_MAJOR 0
#define HYST_VERSION_MINOR 2
#define HYST_VERSION_PATCH 0

/** @cond */
#define HYST_VERSION_STR2_(v) #v
#define HYST_VERSION_STR_(v) HYST_VERSION_STR2_(v)
/** @endcond */
/** "MAJOR.MINOR.PATCH" */
#define HYST_VERSION_STRING                                                  \
    HYST_VERSION_STR_(HYST_VERSION_MAJOR) "." HYST_VERSION_STR_(HYST_VERSION_MINOR) "." \
        HYST_VERSION_STR_(HYST_VERSION_PATCH)

#endif /* HYST_VERSION_H */
