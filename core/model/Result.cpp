// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/model/Result.h"

namespace axistune {

const char* errorCodeName(ErrorCode code)
{
    switch (code) {
    case ErrorCode::BadInput: return "bad input";
    case ErrorCode::OutOfRange: return "out of range";
    case ErrorCode::NotFound: return "not found";
    case ErrorCode::Busy: return "busy";
    case ErrorCode::Device: return "device error";
    case ErrorCode::Safety: return "safety stop";
    case ErrorCode::Aborted: return "aborted";
    case ErrorCode::Io: return "i/o error";
    case ErrorCode::Internal: return "internal error";
    }
    return "error";
}

int exitCodeFor(ErrorCode code)
{
    switch (code) {
    case ErrorCode::BadInput:
    case ErrorCode::OutOfRange:
    case ErrorCode::NotFound: return 2;
    case ErrorCode::Device:
    case ErrorCode::Busy: return 3;
    case ErrorCode::Safety:
    case ErrorCode::Aborted: return 4;
    case ErrorCode::Io:
    case ErrorCode::Internal: return 1;
    }
    return 1;
}

}  // namespace axistune
