/* The system calls the file sandbox needs and OCaml's Unix library does not give: opening
   relative to a folder's descriptor (openat and its kin) and O_NOFOLLOW, so that no symbolic
   link is followed between the sandbox's check of a path and its use (doc/services.md). */

#define _GNU_SOURCE
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <caml/alloc.h>
#include <caml/memory.h>
#include <caml/mlvalues.h>
#include <caml/unixsupport.h>

#ifndef O_CLOEXEC
#define O_CLOEXEC 0
#endif

/* A folder under the root, reached component by component, none of them a link. */
value rs_sandbox_walk(value root, value parts)
{
  CAMLparam2(root, parts);
  int fd = open(String_val(root), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) uerror("open", root);
  mlsize_t n = Wosize_val(parts);
  for (mlsize_t i = 0; i < n; i++) {
    int next = openat(fd, String_val(Field(parts, i)), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    int err = errno;
    close(fd);
    if (next < 0) unix_error(err, "openat", Field(parts, i));
    fd = next;
  }
  CAMLreturn(Val_int(fd));
}

/* Opening never waits (O_NONBLOCK: a FIFO without a peer) and never follows a link as its last
   component; how: 0 read, 1 write, 2 append, 3 write a file that does not exist yet. Nothing is
   truncated here: the caller checks first that it is a regular file. */
value rs_sandbox_open_at(value dir, value name, value how)
{
  CAMLparam3(dir, name, how);
  int flags = O_NOFOLLOW | O_NONBLOCK | O_NOCTTY | O_CLOEXEC;
  switch (Int_val(how)) {
  case 0: flags |= O_RDONLY; break;
  case 1: flags |= O_WRONLY | O_CREAT; break;
  case 2: flags |= O_WRONLY | O_CREAT | O_APPEND; break;
  default: flags |= O_WRONLY | O_CREAT | O_EXCL; break;
  }
  int fd = openat(Int_val(dir), String_val(name), flags, 0644);
  if (fd < 0) uerror("openat", name);
  CAMLreturn(Val_int(fd));
}

/* The kind of an entry, the link itself for a link, in the order of Unix.file_kind, and its
   size; kind -1 when there is no such entry. */
value rs_sandbox_kind_at(value dir, value name)
{
  CAMLparam2(dir, name);
  CAMLlocal1(result);
  struct stat st;
  int kind = -1;
  double size = 0.;
  if (fstatat(Int_val(dir), String_val(name), &st, AT_SYMLINK_NOFOLLOW) == 0) {
    switch (st.st_mode & S_IFMT) {
    case S_IFREG: kind = 0; break;
    case S_IFDIR: kind = 1; break;
    case S_IFCHR: kind = 2; break;
    case S_IFBLK: kind = 3; break;
    case S_IFLNK: kind = 4; break;
    case S_IFIFO: kind = 5; break;
    default: kind = 6; break;
    }
    size = (double) st.st_size;
  } else if (errno != ENOENT && errno != ENOTDIR) {
    uerror("fstatat", name);
  }
  result = caml_alloc_tuple(2);
  Store_field(result, 0, Val_int(kind));
  Store_field(result, 1, caml_copy_double(size));
  CAMLreturn(result);
}

value rs_sandbox_unlink_at(value dir, value name, value folder)
{
  CAMLparam3(dir, name, folder);
  if (unlinkat(Int_val(dir), String_val(name), Bool_val(folder) ? AT_REMOVEDIR : 0) != 0) uerror("unlinkat", name);
  CAMLreturn(Val_unit);
}

value rs_sandbox_mkdir_at(value dir, value name)
{
  CAMLparam2(dir, name);
  if (mkdirat(Int_val(dir), String_val(name), 0755) != 0) uerror("mkdirat", name);
  CAMLreturn(Val_unit);
}

value rs_sandbox_rename_at(value dir1, value name1, value dir2, value name2)
{
  CAMLparam4(dir1, name1, dir2, name2);
  if (renameat(Int_val(dir1), String_val(name1), Int_val(dir2), String_val(name2)) != 0) uerror("renameat", name1);
  CAMLreturn(Val_unit);
}

/* The names in a folder (without . and ..), the folder opened without following a link. */
value rs_sandbox_read_dir_at(value dir, value name)
{
  CAMLparam2(dir, name);
  CAMLlocal1(result);
  int fd = openat(Int_val(dir), String_val(name), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0) uerror("openat", name);
  DIR *d = fdopendir(fd);
  if (d == NULL) { int err = errno; close(fd); unix_error(err, "fdopendir", name); }
  size_t count = 0, capacity = 16;
  int failed = 0;
  char **names = malloc((capacity + 1) * sizeof(char *));
  struct dirent *e;
  if (names == NULL) failed = 1;
  while (!failed && (e = readdir(d)) != NULL) {
    if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0) continue;
    if (count == capacity) {
      char **more = realloc(names, (2 * capacity + 1) * sizeof(char *));
      if (more == NULL) { failed = 1; break; }
      names = more;
      capacity *= 2;
    }
    names[count] = strdup(e->d_name);
    if (names[count] == NULL) { failed = 1; break; }
    count++;
  }
  closedir(d);
  if (!failed) {
    names[count] = NULL;
    result = caml_copy_string_array((const char **) names);
  }
  for (size_t i = 0; i < count; i++) free(names[i]);
  free(names);
  if (failed) unix_error(ENOMEM, "readdir", name);
  CAMLreturn(result);
}
