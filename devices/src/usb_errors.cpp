#include "foldkit/devices/usb_errors.hpp"

#include <libusb.h>

#include <cstdio>

namespace foldkit::devices {

UsbFault usb_fault_from_libusb(int libusb_code) {
  if (libusb_code >= 0) return UsbFault::None;
  switch (libusb_code) {
    case LIBUSB_ERROR_ACCESS:
      return UsbFault::PermissionDenied;
    case LIBUSB_ERROR_BUSY:
      return UsbFault::Busy;
    case LIBUSB_ERROR_NOT_FOUND:
      return UsbFault::NotFound;
    case LIBUSB_ERROR_NO_DEVICE:
      return UsbFault::Unplugged;
    case LIBUSB_ERROR_TIMEOUT:
      return UsbFault::Timeout;
    case LIBUSB_ERROR_PIPE:
      return UsbFault::Stall;
    case LIBUSB_ERROR_OVERFLOW:
      return UsbFault::Overflow;
    case LIBUSB_ERROR_INTERRUPTED:
      return UsbFault::Interrupted;
    case LIBUSB_ERROR_NOT_SUPPORTED:
      return UsbFault::Unsupported;
    default:
      return UsbFault::Io;
  }
}

std::string udev_rule_line(std::uint16_t vendor, std::uint16_t product) {
  char line[160];
  std::snprintf(line, sizeof line,
                "SUBSYSTEM==\"usb\", ATTR{idVendor}==\"%04x\", ATTR{idProduct}==\"%04x\", MODE=\"0660\", "
                "GROUP=\"plugdev\", TAG+=\"uaccess\"",
                vendor, product);
  return line;
}

namespace {

std::string seconds(std::chrono::milliseconds ms) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g s", static_cast<double>(ms.count()) / 1000.0);
  return text;
}

// "after 1200 of 5000 bytes" tells the user how much of the sheet may already be cut.
std::string progress(const UsbFaultContext& c) {
  if (c.bytes_total == 0) return "";
  return " after " + std::to_string(c.bytes_sent) + " of " + std::to_string(c.bytes_total) + " bytes";
}

}  // namespace

std::string usb_fault_message(UsbFault fault, const UsbFaultContext& c) {
  const std::string& dev = c.device.empty() ? std::string("the cutter") : c.device;
  const std::string op = c.operation.empty() ? std::string() : " while " + c.operation;
  switch (fault) {
    case UsbFault::None:
      return dev + ": no error";
    case UsbFault::PermissionDenied:
      return dev + ": permission denied" + op + "; install profiles/udev/" + kUdevRulesFile +
             " (see docs/usb.md) or add this line to /etc/udev/rules.d/" + kUdevRulesFile + ": " +
             udev_rule_line(c.vendor, c.product) +
             " then run `sudo udevadm control --reload && sudo udevadm trigger` and replug the cutter";
    case UsbFault::Busy:
      return dev + " is busy" + op +
             ": another program (Silhouette Studio, an Inkscape plug-in, CUPS) or the kernel printer driver "
             "holds it; close that program or unplug and replug the cutter";
    case UsbFault::NotFound:
      return "no cutter found for " + dev +
             ": check that it is plugged in and switched on (`foldkit devices` lists what is connected)";
    case UsbFault::Unplugged:
      return dev + " was unplugged or switched off" + op + progress(c) +
             "; the job is incomplete, check the mat before sending it again";
    case UsbFault::Timeout:
      return dev + " did not respond within " + seconds(c.waited) + op + progress(c) +
             "; check that it is switched on, loaded and not showing an error";
    case UsbFault::Stall:
      return dev + " rejected the transfer" + op + progress(c) +
             " (endpoint stalled); switch the cutter off and on and send the job again";
    case UsbFault::Overflow:
      return dev + " sent more data than expected" + op + "; is this really a cutter of that model?";
    case UsbFault::Interrupted:
      return dev + ": interrupted" + op + progress(c);
    case UsbFault::Unsupported:
      return dev + ": not supported by this system's USB stack" + op;
    case UsbFault::NoMedia:
      return dev + " reports no media loaded" + progress(c) +
             ": load the mat or paper with the Load button, then send the job again";
    case UsbFault::Paused:
      return dev + " stayed paused for " + seconds(c.waited) + progress(c) +
             ": resume it from its panel or cancel the job there";
    case UsbFault::NoReply:
      return dev + " gave no readable status reply" + op +
             "; it may not speak GP-GL (HP-GL cutters have no status query)";
    case UsbFault::Io:
      break;
  }
  return dev + ": USB input/output error" + op + progress(c) + "; check the cable and try another port";
}

}  // namespace foldkit::devices
