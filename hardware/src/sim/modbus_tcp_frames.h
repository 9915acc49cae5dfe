#pragma once
// Modbus TCP framing and the holding-register functions the simulator serves, written out rather than taken
// from libmodbus's server side: libmodbus reads a request with blocking waits (one slow client stalls every
// other), sleeps half a second before an exception reply to a bad quantity, cannot frame a function code it
// does not know (the rest of the request is then read as the next one) and accepts any protocol id.
//
// A frame is the 7-byte MBAP header (transaction id, protocol id 0, length = 1 + PDU size, unit id) and the
// PDU (function code and data). Every function is answered; a request that breaks a rule of the function
// gets the exception the Modbus specification names (1 illegal function, 2 illegal data address, 3 illegal
// data value), and the frame's length field, not its content, says where the next request begins.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace multidir::hardware::sim {

constexpr std::size_t kMbapSize = 7;
constexpr std::size_t kMaxPduSize = 253;
constexpr int kMaxReadQuantity = 125;   // function 03
constexpr int kMaxWriteQuantity = 123;  // function 16

struct MbapHeader {
  std::uint16_t transaction = 0;
  std::uint16_t protocol = 0;
  std::uint16_t length = 0;  // unit id + PDU bytes
  std::uint8_t unit = 0;
};

// Reads the header from the first kMbapSize bytes.
MbapHeader parseMbap(const std::uint8_t* bytes);

enum class FrameProblem {
  None,
  NotModbus,  // protocol id other than 0: not a Modbus request, the connection is closed
  BadLength,  // a length field that no Modbus PDU can have (below 2 or above 254): framing is lost
};
FrameProblem checkMbap(const MbapHeader& header);

// The request's whole frame size (header + PDU) once its header is known.
inline std::size_t frameSize(const MbapHeader& header) { return 6 + static_cast<std::size_t>(header.length); }

// A block of holding registers, [first, first + count), writable in [firstWritable, lastWritable].
struct RegisterBlock {
  std::uint16_t* registers = nullptr;
  int first = 0;
  int count = 0;
  int firstWritable = 0;
  int lastWritable = -1;
  // The device's own say on a well-formed write to writable registers (`values` for [address, address +
  // values.size())): 0 takes it, else the Modbus exception that refuses it (nothing is written). Optional.
  std::function<int(int address, const std::vector<std::uint16_t>& values)> refuseWrite;
};

struct PduAnswer {
  std::vector<std::uint8_t> pdu;  // the reply's PDU: function code and data, or function | 0x80 and the code
  bool wrote = false;             // registers were written
};

// Answers one request PDU (function code first, `size` bytes) on the block: 03 read, 06 write one,
// 16 write several; every other function code gets exception 1.
PduAnswer answerPdu(const std::uint8_t* pdu, std::size_t size, const RegisterBlock& block);

// The exception reply's PDU.
std::vector<std::uint8_t> exceptionPdu(std::uint8_t function, std::uint8_t code);

// The reply frame to `request`: same transaction id and unit id, protocol 0, the length of `pdu`.
std::vector<std::uint8_t> replyFrame(const MbapHeader& request, const std::vector<std::uint8_t>& pdu);

}  // namespace multidir::hardware::sim
