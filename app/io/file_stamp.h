// What made a file that has no room for metadata of its own (a mesh: OBJ,
// PLY, STL, GLB, VDB), kept beside it so a sequence's rerun can tell its
// own complete frames from broken, stale or foreign ones, as an image
// frame's embedded fingerprint lets it (io/sequence.h frame_is_complete).
//
// The stamp is ".<file name>.stamp.json" beside the file, written
// atomically after the file and its parts:
//
//   {"schema": "marchstudio.stamp/1", "fingerprint": "<32 hex>",
//    "files": [{"name": "out_0001.obj", "bytes": 1234, "hash": "<32 hex>"},
//              {"name": "out_0001.mtl", "bytes": 56, "hash": "<32 hex>"}]}
//
// A file is complete when the stamp reads back, names the same files and
// each has that size and content hash: a truncated or edited file, or one
// rewritten by another run that died before its stamp, is not.
//
//   write_stamp(frame, {frame, mtl}, fingerprint);
//   StampCheck c = check_stamp(frame, {frame, mtl}, fingerprint, &why);
#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace ms {

std::filesystem::path stamp_path(const std::filesystem::path& file);

// `parts`: the file itself first, then any file that goes with it (an
// OBJ's .mtl), all in one directory. Throws system when it cannot be written.
void write_stamp(const std::filesystem::path& file, const std::vector<std::filesystem::path>& parts,
                 const std::string& fingerprint);

enum class StampCheck {
  complete,           // every part as stamped, with this fingerprint
  missing,            // the file is not there
  unmarked,           // the file is there, its stamp is not (or cannot be read)
  other_fingerprint,  // complete, but made from other inputs or settings
  damaged,            // a part is missing, or its size or content differs from the stamp
};

// `why` (may be null) gets the reason for anything but complete and missing.
// Never throws for a bad file.
StampCheck check_stamp(const std::filesystem::path& file, const std::vector<std::filesystem::path>& parts,
                       const std::string& fingerprint, std::string* why = nullptr);

// Removes the stamp of `file`, if any (before the file is made again).
void remove_stamp(const std::filesystem::path& file);

}  // namespace ms
