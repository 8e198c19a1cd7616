#pragma once
/** \file ErrorText.h
 * Exception messages for users: MRPT's exceptions carry a "==== MRPT exception ====" banner and
 * a call-stack backtrace of raw addresses; errorText() keeps only the message lines. */
#include <exception>
#include <string>

namespace hrgbd {

/** `e.what()` without MRPT's banner, "Message:" label, source "Location:" lines and backtrace,
 * lines joined by "; " (other exceptions are returned as they are). */
std::string errorText(const std::exception& e);

}  // namespace hrgbd
