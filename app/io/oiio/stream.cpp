// Image files written through OpenImageIO's scanline writes, a band of
// rows at a time (io/image_stream.h); write() of a whole image is one band.
#include <fcntl.h>
#include <unistd.h>

#include <cstdio>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include "core/error.h"
#include "io/atomic_file.h"
#include "io/oiio/oiio.h"

namespace ms::oiio {
namespace fs = std::filesystem;

namespace {

// OpenImageIO's codecs write through this. It never tells a codec that a
// write failed (OpenImageIO's PNG writer would go on regardless; libjpeg's
// default handler calls exit(1)); the AtomicFile records the failure and
// commit() reports it.
class AtomicProxy final : public OIIO::Filesystem::IOProxy {
 public:
  explicit AtomicProxy(AtomicFile& f) : IOProxy(f.target().string(), Write), f_(f) {}
  const char* proxytype() const override { return "marchstudio-atomic"; }
  size_t write(const void* buf, size_t n) override {
    f_.pwrite(buf, n, static_cast<std::uint64_t>(m_pos));
    m_pos += static_cast<int64_t>(n);
    return n;
  }
  size_t pwrite(const void* buf, size_t n, int64_t offset) override {
    f_.pwrite(buf, n, static_cast<std::uint64_t>(offset));
    return n;
  }
  size_t size() const override { return f_.size(); }

 private:
  AtomicFile& f_;
};

// JPEG has no alpha; 8-bit outputs drop alpha generally (always 1 for renders).
bool drops_alpha(ImageFormat format, const std::vector<std::string>& channels) {
  return is_display_format(format) && channels.size() == 4 && channels[3] == "A";
}

OIIO::ImageSpec output_spec(ImageFormat format, int width, int height, const std::vector<std::string>& channels,
                            const ImageMetadata& meta) {
  const int nch = static_cast<int>(channels.size());
  const bool drop_alpha = drops_alpha(format, channels);
  const int out_ch = drop_alpha ? 3 : nch;
  OIIO::ImageSpec spec(width, height, out_ch, is_display_format(format) ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT);
  spec.channelnames.assign(channels.begin(), channels.begin() + out_ch);
  spec.alpha_channel = (!drop_alpha && nch == 4 && channels[3] == "A") ? 3 : -1;
  if (format == ImageFormat::exr) spec.attribute("compression", "zip");
  if (format == ImageFormat::jpeg) spec.attribute("Compression", "jpeg:95");
  // Fast zlib settings: about 30% larger files, encoding about 3x faster,
  // which keeps sequence writing hidden behind rendering (docs/animation.md).
  if (format == ImageFormat::png) {
    spec.attribute("png:compressionLevel", 1);
    spec.attribute("png:filter", 16);  // PNG_FILTER_SUB
  }
  // Past 4 GiB a classic TIFF's offsets overflow (a tiled still can get there).
  if (format == ImageFormat::tiff && static_cast<double>(width) * height * out_ch > 3.5 * 1024 * 1024 * 1024)
    spec.attribute("tiff:bigtiff", 1);
  spec.attribute("oiio:ColorSpace", is_display_format(format) ? "sRGB" : "Linear");
  for (const auto& [k, v] : meta) spec.attribute(k, v);
  return spec;
}

// The members die in reverse order: the codec (which may still write
// through the proxy) before the proxy before the file, whose destructor
// removes the temporary unless it was committed.
class OiioRowWriter final : public ImageRowWriter {
 public:
  OiioRowWriter(const fs::path& path, ImageFormat format, int width, int height,
                const std::vector<std::string>& channels, const ImageMetadata& meta)
      : file_(path), proxy_(file_), by_name_(format == ImageFormat::tiff), nch_(static_cast<int>(channels.size())) {
    // The format comes from the target's name; the bytes go to the
    // temporary: through the proxy, which checks every write (PNG and JPEG
    // do not), or for TIFF by name, since libtiff rereads the directory it
    // wrote (to link the EXIF one) and checks its own writes.
    if (by_name_ && file_.temp().empty())  // a FIFO or a device (io/atomic_file.h): nothing to reread
      fail_input("a TIFF cannot be written to a FIFO or a device (libtiff rereads what it wrote)", path.string(),
                 0, "-o", "write a .png, .jpg or .exr there, or a TIFF to a regular file");
    out_ = OIIO::ImageOutput::create(path.string(), by_name_ ? nullptr : &proxy_);
    if (!out_) fail_system("cannot create an image writer: " + OIIO::geterror(), path.string());
    spec_ = output_spec(format, width, height, channels, meta);
  }

  void write_rows(int y0, const Image& rows) override {
    // Opened with the first rows: a writer given up before any (a
    // --timeout in the first band) is never opened, and libpng has no
    // empty file to complain about on stderr when it is closed.
    if (!opened_) {
      if (!out_->open(by_name_ ? file_.temp().string() : file_.target().string(), spec_)) fail();
      opened_ = true;
    }
    const OIIO::stride_t xstride = static_cast<OIIO::stride_t>(nch_ * sizeof(float));
    if (!out_->write_scanlines(y0, y0 + rows.height, 0, OIIO::TypeDesc::FLOAT, rows.pixels.data(), xstride)) fail();
    check_file();  // a full disk ends a long render at once, not at the end
  }

  ~OiioRowWriter() override { abandon(); }  // without finish(): then file_ removes the temporary

  fs::path temp() const override { return file_.temp(); }

  void finish() override {
    const bool ok = out_->close();
    if (!ok) fail();
    if (by_name_) file_.written_by_name();
    out_.reset();
    file_.commit();
  }

 private:
  [[noreturn]] void fail() {
    const std::string err = out_->geterror();
    abandon();
    if (by_name_)  // the writer's own check failed: the same words as AtomicFile's
      fail_system("cannot write the file: " + err.substr(0, err.find('\n')) + "; nothing was written",
                  file_.target().string());
    if (file_.failed()) file_.commit();  // throws AtomicFile's words (the errno), removing the temporary
    fail_system("cannot write image: " + err, file_.target().string());
  }
  void check_file() {
    if (!file_.failed()) return;
    abandon();
    file_.commit();  // throws
  }
  // A codec given up half way is closed with stderr silenced: libpng
  // reports a file it never finished ("No IDATs written into file") on
  // stderr, though its temporary is removed anyway and the error that
  // ended the write is the one line the user gets.
  void abandon() {
    if (!out_) return;
    std::fflush(stderr);
    const int saved = ::dup(2), null = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
    if (saved >= 0 && null >= 0) ::dup2(null, 2);
    out_.reset();
    if (saved >= 0 && null >= 0) ::dup2(saved, 2);
    if (saved >= 0) ::close(saved);
    if (null >= 0) ::close(null);
  }

  AtomicFile file_;
  AtomicProxy proxy_;
  const bool by_name_;
  const int nch_;
  OIIO::ImageSpec spec_;
  bool opened_ = false;
  std::unique_ptr<OIIO::ImageOutput> out_;
};

}  // namespace

std::unique_ptr<ImageRowWriter> open_rows(const fs::path& path, ImageFormat format, int width, int height,
                                          const std::vector<std::string>& channels, const ImageMetadata& meta) {
  return std::make_unique<OiioRowWriter>(path, format, width, height, channels, meta);
}

void write(const Image& image, const fs::path& path, ImageFormat format, const ImageMetadata& meta) {
  OiioRowWriter w(path, format, image.width, image.height, image.channels, meta);
  w.write_rows(0, image);
  w.finish();
}

}  // namespace ms::oiio
