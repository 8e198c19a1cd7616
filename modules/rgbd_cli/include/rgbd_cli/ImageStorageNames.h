#pragma once
/** \file ImageStorageNames.h
 * The names of hrgbd::ImageStorage on the command line (`--images` of tum2rawlog and
 * rgbd-simulate): `CommandLine::oneOf<ImageStorage>()` lists them, `parseEnum<ImageStorage>()`
 * (rgbd_core/Config.h) converts. For apps that link rgbd_io. */
#include <mrpt/typemeta/TEnumType.h>

#include "rgbd_io/RawlogWriter.h"

MRPT_ENUM_TYPE_BEGIN(hrgbd::ImageStorage)
MRPT_FILL_ENUM_CUSTOM_NAME(hrgbd::ImageStorage::Inline, "inline");
MRPT_FILL_ENUM_CUSTOM_NAME(hrgbd::ImageStorage::ExternalPng, "png");
MRPT_FILL_ENUM_CUSTOM_NAME(hrgbd::ImageStorage::ExternalJpeg, "jpg");
MRPT_ENUM_TYPE_END()
