#include "foldkit/devices/usb_transport.hpp"

#include <libusb.h>

#include <algorithm>
#include <cstdio>
#include <limits>

#include "foldkit/error.hpp"

namespace foldkit::devices {
namespace {

struct ContextDeleter {
  void operator()(libusb_context* c) const { libusb_exit(c); }
};
struct HandleDeleter {
  void operator()(libusb_device_handle* h) const { libusb_close(h); }
};
struct ListDeleter {
  void operator()(libusb_device** list) const { libusb_free_device_list(list, 1); }
};
struct ConfigDeleter {
  void operator()(libusb_config_descriptor* c) const { libusb_free_config_descriptor(c); }
};
using Context = std::unique_ptr<libusb_context, ContextDeleter>;
using Handle = std::unique_ptr<libusb_device_handle, HandleDeleter>;
using DeviceList = std::unique_ptr<libusb_device*, ListDeleter>;
using Config = std::unique_ptr<libusb_config_descriptor, ConfigDeleter>;

constexpr int kInterface = 0;

Context make_context() {
  libusb_context* raw = nullptr;
  const int rc = libusb_init(&raw);
  if (rc != LIBUSB_SUCCESS) {
    throw DeviceError(std::string("cannot use USB: ") + libusb_strerror(static_cast<libusb_error>(rc)));
  }
  return Context(raw);
}

struct Listed {
  DeviceList list;
  std::span<libusb_device*> devices;
};

Listed list_devices(libusb_context* ctx) {
  libusb_device** raw = nullptr;
  const ssize_t n = libusb_get_device_list(ctx, &raw);
  if (n < 0) {
    throw DeviceError(std::string("cannot list USB devices: ") +
                      libusb_strerror(static_cast<libusb_error>(n)));
  }
  return {DeviceList(raw), std::span<libusb_device*>(raw, static_cast<std::size_t>(n))};
}

std::optional<FoundDevice> match(libusb_device* dev, std::span<const UsbId> known) {
  libusb_device_descriptor d{};
  if (libusb_get_device_descriptor(dev, &d) != LIBUSB_SUCCESS) return std::nullopt;
  FoundDevice found;
  found.bus = libusb_get_bus_number(dev);
  found.address = libusb_get_device_address(dev);
  const auto it = std::find_if(known.begin(), known.end(), [&](const UsbId& id) {
    return id.vendor == d.idVendor && id.product == d.idProduct;
  });
  if (it != known.end()) {
    found.id = *it;
    found.known_model = true;
    return found;
  }
  // Hubs of a cutter vendor would be noise; cutters are class 0 (per interface) or printer class.
  if (!is_cutter_vendor(d.idVendor) || d.bDeviceClass == LIBUSB_CLASS_HUB) return std::nullopt;
  found.id = {d.idVendor, d.idProduct, "unknown model"};
  return found;
}

UsbAccess probe_access(libusb_device* dev) {
  libusb_device_handle* raw = nullptr;
  const int rc = libusb_open(dev, &raw);
  if (rc == LIBUSB_SUCCESS) {
    libusb_close(raw);
    return UsbAccess::Ok;
  }
  return rc == LIBUSB_ERROR_ACCESS ? UsbAccess::PermissionDenied : UsbAccess::Unknown;
}

// The bulk pipes of interface 0 over libusb, with the packet sizes its descriptors declare.
class LibusbPipes final : public BulkPipes {
 public:
  LibusbPipes(libusb_device_handle* handle, std::uint8_t out_ep, std::size_t out_packet,
              std::optional<std::uint8_t> in_ep, std::size_t in_packet)
      : handle_(handle), out_ep_(out_ep), in_ep_(in_ep), out_packet_(out_packet), in_packet_(in_packet) {}

  UsbTransfer write_some(std::span<const std::byte> bytes, std::chrono::milliseconds timeout) override {
    return transfer(out_ep_, const_cast<std::byte*>(bytes.data()), bytes.size(), timeout);
  }
  UsbTransfer read_some(std::span<std::byte> buffer, std::chrono::milliseconds timeout) override {
    if (!in_ep_) return {UsbFault::Unsupported, 0};
    return transfer(*in_ep_, buffer.data(), buffer.size(), timeout);
  }
  std::size_t out_packet_bytes() const override { return out_packet_; }
  std::size_t in_packet_bytes() const override { return in_ep_ ? in_packet_ : 0; }

 private:
  UsbTransfer transfer(std::uint8_t ep, std::byte* data, std::size_t size,
                       std::chrono::milliseconds timeout) {
    // libusb takes int lengths and unsigned timeouts where 0 means "forever": clamp both so no wait is
    // unbounded.
    const int length = static_cast<int>(std::min<std::size_t>(size, std::numeric_limits<int>::max()));
    const auto ms = static_cast<unsigned>(std::clamp<long long>(timeout.count(), 1, 24LL * 3600 * 1000));
    int moved = 0;
    const int rc =
        libusb_bulk_transfer(handle_, ep, reinterpret_cast<unsigned char*>(data), length, &moved, ms);
    return {usb_fault_from_libusb(rc), static_cast<std::size_t>(std::max(moved, 0))};
  }

  libusb_device_handle* handle_;
  std::uint8_t out_ep_;
  std::optional<std::uint8_t> in_ep_;
  std::size_t out_packet_, in_packet_;
};

struct Endpoints {
  std::optional<std::uint8_t> out, in;
  std::size_t out_packet = 0, in_packet = 0;
  int configuration = 1;
};

Endpoints find_endpoints(libusb_device* dev) {
  libusb_config_descriptor* raw = nullptr;
  if (libusb_get_active_config_descriptor(dev, &raw) != LIBUSB_SUCCESS &&
      libusb_get_config_descriptor(dev, 0, &raw) != LIBUSB_SUCCESS) {
    return {};
  }
  const Config config(raw);
  Endpoints eps;
  eps.configuration = config->bConfigurationValue;
  if (config->bNumInterfaces <= kInterface || config->interface[kInterface].num_altsetting < 1) return eps;
  const libusb_interface_descriptor& alt = config->interface[kInterface].altsetting[0];
  for (int i = 0; i < alt.bNumEndpoints; ++i) {
    const libusb_endpoint_descriptor& ep = alt.endpoint[i];
    if ((ep.bmAttributes & LIBUSB_TRANSFER_TYPE_MASK) != LIBUSB_TRANSFER_TYPE_BULK) continue;
    // Bits 0..10 are the packet size; high-speed devices put extra-transaction bits above.
    const std::size_t packet = ep.wMaxPacketSize & 0x7ffu;
    if ((ep.bEndpointAddress & LIBUSB_ENDPOINT_DIR_MASK) == LIBUSB_ENDPOINT_IN) {
      if (!eps.in) eps.in = ep.bEndpointAddress, eps.in_packet = packet;
    } else if (!eps.out) {
      eps.out = ep.bEndpointAddress, eps.out_packet = packet;
    }
  }
  return eps;
}

}  // namespace

std::string describe_usb_device(const FoundDevice& d) {
  char where[48];
  std::snprintf(where, sizeof where, " (usb %03u:%03u, %04x:%04x)", d.bus, d.address, d.id.vendor,
                d.id.product);
  return (d.known_model ? d.id.model : std::string("unknown cutter")) + where;
}

std::vector<FoundDevice> find_usb_cutters(std::span<const UsbId> known) {
  const Context ctx = make_context();
  const Listed listed = list_devices(ctx.get());
  std::vector<FoundDevice> found;
  for (libusb_device* dev : listed.devices) {
    if (auto f = match(dev, known)) {
      f->access = probe_access(dev);
      found.push_back(*f);
    }
  }
  std::sort(found.begin(), found.end(), [](const FoundDevice& a, const FoundDevice& b) {
    return std::pair(a.bus, a.address) < std::pair(b.bus, b.address);
  });
  return found;
}

struct UsbTransport::Impl {
  Context ctx;
  Handle handle;
  FoundDevice device;
  bool claimed = false;
  bool reattach = false;
  std::unique_ptr<LibusbPipes> pipes;
  std::unique_ptr<UsbSession> session;

  void release() noexcept {
    session.reset();
    pipes.reset();
    if (handle && claimed) libusb_release_interface(handle.get(), kInterface);
    // Give the device back to usblp so /dev/usb/lpN works again for other tools.
    if (handle && reattach) libusb_attach_kernel_driver(handle.get(), kInterface);
    claimed = reattach = false;
    handle.reset();
    ctx.reset();
  }
  ~Impl() { release(); }
};

UsbTransport::UsbTransport(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
UsbTransport::UsbTransport(UsbTransport&&) noexcept = default;
UsbTransport& UsbTransport::operator=(UsbTransport&&) noexcept = default;
UsbTransport::~UsbTransport() = default;

namespace {
UsbSession& live(const std::unique_ptr<UsbTransport::Impl>& impl) {
  if (!impl || !impl->session) throw DeviceError("USB cutter: used after close");
  return *impl->session;
}
}  // namespace

void UsbTransport::write(std::span<const std::byte> bytes) {
  live(impl_).write(bytes);
}
DeviceState UsbTransport::status() {
  return live(impl_).status();
}
std::optional<std::vector<std::byte>> UsbTransport::request(std::span<const std::byte> command,
                                                            std::chrono::milliseconds timeout) {
  UsbSession& session = live(impl_);
  if (in_packet_bytes() == 0) {
    session.write(command);
    return std::nullopt;
  }
  return session.query(command, timeout);
}
void UsbTransport::close() {
  if (impl_) impl_->release();
}
std::string UsbTransport::describe() const {
  return impl_ ? describe_usb_device(impl_->device) : std::string("usb (closed)");
}
std::size_t UsbTransport::out_packet_bytes() const {
  return impl_ && impl_->pipes ? impl_->pipes->out_packet_bytes() : 0;
}
std::size_t UsbTransport::in_packet_bytes() const {
  return impl_ && impl_->pipes ? impl_->pipes->in_packet_bytes() : 0;
}
std::size_t UsbTransport::bytes_sent() const {
  return impl_ && impl_->session ? impl_->session->bytes_sent() : 0;
}

std::unique_ptr<UsbTransport> open_usb_cutter(const UsbSelector& selector, const UsbOptions& options) {
  auto impl = std::make_unique<UsbTransport::Impl>();
  impl->ctx = make_context();
  UsbFaultContext fc;
  fc.vendor = selector.id.vendor;
  fc.product = selector.id.product;
  {
    char ids[16];
    std::snprintf(ids, sizeof ids, "%04x:%04x", selector.id.vendor, selector.id.product);
    fc.device = selector.id.model.empty() ? std::string("usb ") + ids : selector.id.model + " (" + ids + ")";
  }
  const auto fail = [&](int rc, const char* operation) {
    fc.operation = operation;
    throw DeviceError(usb_fault_message(usb_fault_from_libusb(rc), fc));
  };

  const Listed listed = list_devices(impl->ctx.get());
  const UsbId known[] = {selector.id};
  libusb_device* chosen = nullptr;
  for (libusb_device* dev : listed.devices) {
    const auto f = match(dev, known);
    if (!f || !f->known_model) continue;
    if (selector.bus && *selector.bus != f->bus) continue;
    if (selector.address && *selector.address != f->address) continue;
    chosen = dev;
    impl->device = *f;
    break;
  }
  if (!chosen) fail(LIBUSB_ERROR_NOT_FOUND, "looking for it");
  if (impl->device.id.model.empty()) impl->device.id.model = "cutter";
  fc.device = describe_usb_device(impl->device);

  libusb_device_handle* raw = nullptr;
  if (const int rc = libusb_open(chosen, &raw); rc != LIBUSB_SUCCESS) fail(rc, "opening");
  impl->handle.reset(raw);
  libusb_device_handle* h = impl->handle.get();

  // usblp binds printer-class cutters; claiming under it reports busy.
  if (libusb_kernel_driver_active(h, kInterface) == 1) {
    if (const int rc = libusb_detach_kernel_driver(h, kInterface); rc != LIBUSB_SUCCESS) {
      fail(rc, "detaching the kernel printer driver");
    }
    impl->reattach = true;
  }
  const Endpoints eps = find_endpoints(chosen);
  if (!eps.out) {
    throw DeviceError(fc.device + ": no bulk OUT endpoint on interface 0; is this a cutter?");
  }
  // Only set the configuration when it differs: setting it again resets some devices, and usbip and
  // umockdev reject it. A failure other than busy is left for the claim to report.
  int current = 0;
  if (libusb_get_configuration(h, &current) == LIBUSB_SUCCESS && current != eps.configuration) {
    const int rc = libusb_set_configuration(h, eps.configuration);
    if (rc == LIBUSB_ERROR_BUSY || rc == LIBUSB_ERROR_NO_DEVICE || rc == LIBUSB_ERROR_ACCESS) {
      fail(rc, "configuring");
    }
  }
  if (const int rc = libusb_claim_interface(h, kInterface); rc != LIBUSB_SUCCESS) {
    fail(rc, "claiming interface 0");
  }
  impl->claimed = true;
  impl->pipes = std::make_unique<LibusbPipes>(h, *eps.out, eps.out_packet, eps.in, eps.in_packet);
  impl->session = std::make_unique<UsbSession>(*impl->pipes, options, fc);
  return std::make_unique<UsbTransport>(std::move(impl));
}

}  // namespace foldkit::devices
