# Helpers for the adversarial cases (sourced by each case's `run`; see README.md).

# full_fs KIB COMMAND...: runs COMMAND with the current folder's `small/` on a filesystem
# of KIB KiB, so that writes fail with "No space left on device" once it is full. A
# private tmpfs where the machine allows one (a mount namespace: root, or an unprivileged
# user namespace); elsewhere a file-size limit of KIB KiB (write(2) then fails with
# EFBIG, which the harness shows as the full disk's ENOSPC so that the snapshot is one).
full_fs() {
  local kib=$1
  shift
  mkdir -p small
  if unshare --mount --propagation private true 2>/dev/null; then
    unshare --mount --propagation private -- bash -c \
      'mount -t tmpfs -o size="$0"k tmpfs small && exec "$@"' "$kib" "$@"
  elif unshare --user --map-root-user --mount --propagation private true 2>/dev/null; then
    unshare --user --map-root-user --mount --propagation private -- bash -c \
      'mount -t tmpfs -o size="$0"k tmpfs small && exec "$@"' "$kib" "$@"
  else
    bash -c 'trap "" XFSZ; ulimit -f "$0"; exec "$@"' "$kib" "$@"
  fi
}

# kind PATH...: what each path is (regular file, symbolic link, fifo, character special
# file), its permission bits and number of links, and its size for a regular file.
kind() {
  local p
  for p in "$@"; do
    if [ -L "$p" ]; then
      echo "$p: symbolic link -> $(readlink "$p")"
    elif [ -e "$p" ]; then
      stat -c "$p: %F %a links=%h size=%s" "$p"
    else
      echo "$p: missing"
    fi
  done
}

# status COMMAND...: runs COMMAND, then prints its exit status.
status() {
  "$@"
  echo "exit: $?"
}

# shown COMMAND...: runs COMMAND with standard error joined to standard output, prints what
# it wrote with the colour sequences (SGR, `ESC [ … m`) and a line-ending carriage return
# (a terminal's) taken out, then its exit status. If anything a terminal would act on is
# left (a control character other than tab and newline, a C1 control, a line separator or
# a bidirectional control), the output is shown with `cat -v` after `UNSAFE OUTPUT:`.
shown() {
  local status
  "$@" > .shown 2>&1
  status=$?
  LC_ALL=C sed -e 's/\x1b\[[0-9;]*m//g' -e 's/\r$//' .shown > .shown.plain
  if LC_ALL=C grep -qaP '[\x00-\x08\x0b-\x1f\x7f]|\xc2[\x80-\x9f]|\xe2\x80[\xa8-\xae]|\xe2\x81[\xa6-\xa9]' .shown.plain; then
    echo "UNSAFE OUTPUT:"
    cat -v .shown.plain
  else
    cat .shown.plain
  fi
  echo "exit: $status"
  rm -f .shown .shown.plain
}
