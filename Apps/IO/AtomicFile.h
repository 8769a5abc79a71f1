#ifndef AtomicFile_h
#define AtomicFile_h

#include <string>

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
 * written in place.
 *
 * Throws RuntimeError("cannot write '<path>': <why>") on any failure (a full
 * disk, a file-size limit, a directory without write permission), after
 * removing the temporary file.
 */
void WriteFileAtomically(const std::string& path, const std::string& bytes);

} // namespace cli

#endif
