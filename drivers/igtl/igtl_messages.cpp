/// @file igtl_messages.cpp
/// @brief Eigen matrices into igtl::Matrix4x4 (float, row-major) and the library's Pack().
#include "drivers/igtl/igtl_messages.h"

#include <igtlQuaternionTrackingDataMessage.h>
#include <igtlStatusMessage.h>
#include <igtlTrackingDataMessage.h>
#include <igtlTransformMessage.h>
#include <igtl_util.h>

namespace lungar::drivers {

namespace {

void to_igtl(const Eigen::Matrix4d& m, igtl::Matrix4x4& out) {
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) out[i][j] = static_cast<float>(m(i, j));
  }
}

template <typename Message>
std::vector<std::uint8_t> packed(Message& msg, const std::string& device, IgtlTime time) {
  msg->SetDeviceName(device.c_str());
  msg->SetTimeStamp(time.seconds, time.fraction);
  msg->Pack();
  const auto* p = static_cast<const std::uint8_t*>(msg->GetPackPointer());
  return std::vector<std::uint8_t>(p, p + msg->GetPackSize());
}

/// A TDATA or QTDATA message: one 6-D element a tool, named after it; `set_pose(msg, element, tool)` writes the
/// tool's pose in the message's own form and adds the element.
template <typename Message, typename Element, typename SetPose>
std::vector<std::uint8_t> tracking_message(const std::string& device, std::span<const IgtlTool> tools, IgtlTime time,
                                           const SetPose& set_pose) {
  auto msg = Message::New();
  for (const IgtlTool& tool : tools) {
    auto e = Element::New();
    e->SetName(tool.name.c_str());
    e->SetType(Element::TYPE_6D);
    set_pose(msg, e, tool);
  }
  return packed(msg, device, time);
}

}  // namespace

IgtlTime IgtlTime::from_ns(std::uint64_t unix_ns) {
  return {static_cast<std::uint32_t>(unix_ns / 1'000'000'000u),
          igtl_nanosec_to_frac(static_cast<igtl_uint32>(unix_ns % 1'000'000'000u))};
}

std::vector<std::uint8_t> igtl_transform_message(const std::string& device, const Eigen::Matrix4d& matrix,
                                                 IgtlTime time) {
  auto msg = igtl::TransformMessage::New();
  igtl::Matrix4x4 m;
  to_igtl(matrix, m);
  msg->SetMatrix(m);
  return packed(msg, device, time);
}

std::vector<std::uint8_t> igtl_tdata_message(const std::string& device, std::span<const IgtlTool> tools,
                                             IgtlTime time) {
  return tracking_message<igtl::TrackingDataMessage, igtl::TrackingDataElement>(
      device, tools, time, [](auto& msg, auto& e, const IgtlTool& tool) {
        igtl::Matrix4x4 m;
        to_igtl(tool.matrix, m);
        e->SetMatrix(m);
        msg->AddTrackingDataElement(e);
      });
}

std::vector<std::uint8_t> igtl_qtdata_message(const std::string& device, std::span<const IgtlTool> tools,
                                              IgtlTime time) {
  return tracking_message<igtl::QuaternionTrackingDataMessage, igtl::QuaternionTrackingDataElement>(
      device, tools, time, [](auto& msg, auto& e, const IgtlTool& tool) {
        const Eigen::Quaterniond q(Eigen::Matrix3d(tool.matrix.topLeftCorner<3, 3>()));
        const Eigen::Vector3f t = tool.matrix.topRightCorner<3, 1>().cast<float>();
        e->SetPosition(t.x(), t.y(), t.z());
        e->SetQuaternion(static_cast<float>(q.x()), static_cast<float>(q.y()), static_cast<float>(q.z()),
                         static_cast<float>(q.w()));
        msg->AddQuaternionTrackingDataElement(e);
      });
}

std::vector<std::uint8_t> igtl_status_message(const std::string& device, IgtlTime time) {
  auto msg = igtl::StatusMessage::New();
  msg->SetCode(igtl::StatusMessage::STATUS_OK);
  msg->SetStatusString("lungar test");
  return packed(msg, device, time);
}

}  // namespace lungar::drivers
