// SPDX-License-Identifier: GPL-3.0-or-later
// One client's byte stream through the server's request handling, without the network loop.
#include "core/device/SimDriveServer.h"

#include <modbus/modbus.h>
#include <vector>

namespace axistune::device {

void SimDriveServer::serveStream(int fd)
{
    modbus_t* ctx = static_cast<modbus_t*>(m_ctx);
    std::vector<std::uint8_t> query(MODBUS_TCP_MAX_ADU_LENGTH);
    modbus_set_socket(ctx, fd);
    while (true) {
        const int rc = modbus_receive(ctx, query.data());
        if (rc <= 0)
            break;
        reply(query.data(), rc);
        step();
    }
    modbus_set_socket(ctx, -1);
}

} // namespace axistune::device
