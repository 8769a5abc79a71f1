#ifndef AtomicFile_h
#define AtomicFile_h

#include <string>
#include <vector>

namespace cli
{

/**
 * Writes `bytes` to `path` so that a failure never leaves half a file there:
 * the bytes go to a temporary file in the same directory, which is renamed
 * onto `path` only when every byte is written and the file closed. The new
 * file gets the old one's permissions, or 0666 less the umask.
 *
 * A symbolic link is followed: its target is replaced, the link kept. A path
 * that exists and is not a regular file (/dev/null, /dev/stdout, a pipe) is
 * written in place. An existing file the user may not write (access(2),
 * with the real user id: a file of one's own made read-only too) is
 * refused, though the rename could replace it; a file made read-only
 * after that check and before the rename is still replaced.
 *
 * Throws RuntimeError("cannot write '<path>': <why>") on any failure (a full
 * disk, a file-size limit, a directory without write permission), after
 * removing the temporary file.
 */
void WriteFileAtomically(const std::string& path, const std::string& bytes);

/**
 * Several files written as one, so a failure leaves none of them changed
 * (smooth -o MESH --lines-output LINES once left MESH written when LINES
 * could not be): Add() writes each file's temporary beside it at once, and
 * Commit() renames them all onto their targets. A failure in Add() throws
 * as WriteFileAtomically() does; the destructor removes the temporaries of
 * a batch not committed. A device or pipe, written in place, is written
 * first in Commit(). Only a rename failing half-way through Commit() (the
 * directory changed meanwhile) can leave some targets new and some old.
 */
class FileBatch
{
public:
  FileBatch() = default;
  FileBatch(const FileBatch&) = delete;
  FileBatch& operator=(const FileBatch&) = delete;
  ~FileBatch();

  void Add(const std::string& path, const std::string& bytes);
  void Commit();

private:
  struct Pending
  {
    std::string Path;      ///< as the user gave it, for messages
    std::string Target;    ///< the link's target when it is a link
    std::string Temporary; ///< empty: written in place at Commit()
    std::string Bytes;     ///< for a file written in place
  };
  std::vector<Pending> Files;
};

} // namespace cli

#endif
