#include "sim/modbus_tcp_frames.h"

namespace multidir::hardware::sim {
namespace {

constexpr std::uint8_t kIllegalFunction = 1;
constexpr std::uint8_t kIllegalDataAddress = 2;
constexpr std::uint8_t kIllegalDataValue = 3;

std::uint16_t word(const std::uint8_t* bytes) {
  return static_cast<std::uint16_t>((static_cast<unsigned>(bytes[0]) << 8) | bytes[1]);
}

void putWord(std::vector<std::uint8_t>& out, std::uint16_t value) {
  out.push_back(static_cast<std::uint8_t>(value >> 8));
  out.push_back(static_cast<std::uint8_t>(value & 0xFFu));
}

bool inBlock(const RegisterBlock& block, int address, int quantity) {
  return address >= block.first && address + quantity <= block.first + block.count;
}

bool writable(const RegisterBlock& block, int address, int quantity) {
  return address >= block.firstWritable && address + quantity - 1 <= block.lastWritable;
}

int deviceRefusal(const RegisterBlock& block, int address, const std::vector<std::uint16_t>& values) {
  return block.refuseWrite ? block.refuseWrite(address, values) : 0;
}

PduAnswer readHolding(const std::uint8_t* pdu, std::size_t size, const RegisterBlock& block) {
  if (size != 5) return {exceptionPdu(pdu[0], kIllegalDataValue), false};
  const int address = word(pdu + 1);
  const int quantity = word(pdu + 3);
  if (quantity < 1 || quantity > kMaxReadQuantity) return {exceptionPdu(pdu[0], kIllegalDataValue), false};
  if (!inBlock(block, address, quantity)) return {exceptionPdu(pdu[0], kIllegalDataAddress), false};
  PduAnswer answer;
  answer.pdu.push_back(pdu[0]);
  answer.pdu.push_back(static_cast<std::uint8_t>(2 * quantity));
  for (int i = 0; i < quantity; ++i) putWord(answer.pdu, block.registers[address - block.first + i]);
  return answer;
}

PduAnswer writeSingle(const std::uint8_t* pdu, std::size_t size, const RegisterBlock& block) {
  if (size != 5) return {exceptionPdu(pdu[0], kIllegalDataValue), false};
  const int address = word(pdu + 1);
  if (!inBlock(block, address, 1) || !writable(block, address, 1))
    return {exceptionPdu(pdu[0], kIllegalDataAddress), false};
  if (const int refusal = deviceRefusal(block, address, {word(pdu + 3)}); refusal != 0)
    return {exceptionPdu(pdu[0], static_cast<std::uint8_t>(refusal)), false};
  block.registers[address - block.first] = word(pdu + 3);
  return {std::vector<std::uint8_t>(pdu, pdu + 5), true};
}

PduAnswer writeMultiple(const std::uint8_t* pdu, std::size_t size, const RegisterBlock& block) {
  if (size < 6) return {exceptionPdu(pdu[0], kIllegalDataValue), false};
  const int address = word(pdu + 1);
  const int quantity = word(pdu + 3);
  const std::size_t bytes = pdu[5];
  if (quantity < 1 || quantity > kMaxWriteQuantity || bytes != 2u * static_cast<std::size_t>(quantity) ||
      size != 6 + bytes)
    return {exceptionPdu(pdu[0], kIllegalDataValue), false};
  if (!inBlock(block, address, quantity) || !writable(block, address, quantity))
    return {exceptionPdu(pdu[0], kIllegalDataAddress), false};
  std::vector<std::uint16_t> values(static_cast<std::size_t>(quantity));
  for (int i = 0; i < quantity; ++i) values[static_cast<std::size_t>(i)] = word(pdu + 6 + 2 * i);
  if (const int refusal = deviceRefusal(block, address, values); refusal != 0)
    return {exceptionPdu(pdu[0], static_cast<std::uint8_t>(refusal)), false};
  for (int i = 0; i < quantity; ++i) block.registers[address - block.first + i] = values[static_cast<std::size_t>(i)];
  PduAnswer answer;
  answer.wrote = true;
  answer.pdu.push_back(pdu[0]);
  putWord(answer.pdu, static_cast<std::uint16_t>(address));
  putWord(answer.pdu, static_cast<std::uint16_t>(quantity));
  return answer;
}

}  // namespace

MbapHeader parseMbap(const std::uint8_t* bytes) {
  MbapHeader header;
  header.transaction = word(bytes);
  header.protocol = word(bytes + 2);
  header.length = word(bytes + 4);
  header.unit = bytes[6];
  return header;
}

FrameProblem checkMbap(const MbapHeader& header) {
  if (header.protocol != 0) return FrameProblem::NotModbus;
  if (header.length < 2 || header.length > kMaxPduSize + 1) return FrameProblem::BadLength;
  return FrameProblem::None;
}

std::vector<std::uint8_t> exceptionPdu(std::uint8_t function, std::uint8_t code) {
  return {static_cast<std::uint8_t>(function | 0x80u), code};
}

PduAnswer answerPdu(const std::uint8_t* pdu, std::size_t size, const RegisterBlock& block) {
  switch (pdu[0]) {
    case 0x03: return readHolding(pdu, size, block);
    case 0x06: return writeSingle(pdu, size, block);
    case 0x10: return writeMultiple(pdu, size, block);
    default: return {exceptionPdu(pdu[0], kIllegalFunction), false};
  }
}

std::vector<std::uint8_t> replyFrame(const MbapHeader& request, const std::vector<std::uint8_t>& pdu) {
  std::vector<std::uint8_t> frame;
  frame.reserve(kMbapSize + pdu.size());
  putWord(frame, request.transaction);
  putWord(frame, 0);
  putWord(frame, static_cast<std::uint16_t>(pdu.size() + 1));
  frame.push_back(request.unit);
  frame.insert(frame.end(), pdu.begin(), pdu.end());
  return frame;
}

}  // namespace multidir::hardware::sim
