#!/bin/bash
# The tests' stand-in for VPL's jail (vpl-jail-system): runs vpl_evaluate.sh in HOME, then the
# vpl_execution it left, as the unprivileged UID with no_new_privs (setpriv), with only HOME, TMPDIR,
# PATH, TERM, USER and VPL_LANG set. Prints the evaluation's output, then ---EXECUTION--- and
# vpl_execution's output. Needs root.
#   MODE plain:  as the jail's user, in the machine's own file system;
#   MODE pivot:  in new mount, pid and ipc namespaces whose root is made with pivot_root (vpl-jail-system 5.x);
#   MODE chroot: in a chroot (vpl-jail-system 4.x, or 5.x with USE_NAMESPACE=false).
# usage: jail.sh MODE HOME UID TICK1_HOME   (TICK1_HOME: tick1's installation, seen at the same path inside)
mode=$1 home=$2 uid=$3 tick1home=$4
run='cd "$HOME" && ./vpl_evaluate.sh; echo ---EXECUTION---; if [ -x vpl_execution ] ; then ./vpl_execution; fi'
if [ "$mode" = plain ] ; then
    exec env -i HOME="$home" PATH=/usr/bin:/bin TERM=xterm USER="p$uid" VPL_LANG=en_US.UTF-8 TMPDIR=/tmp \
        setpriv --reuid="$uid" --regid="$uid" --clear-groups --no-new-privs bash -c "$run"
fi
root=$(mktemp -d /tmp/tick1-jail-root.XXXXXX)
unshare --mount --pid --ipc --fork bash -s "$mode" "$root" "$home" "$uid" "$run" "$tick1home" <<'INSIDE'
set -e
mode=$1 root=$2 home=$3 uid=$4 run=$5 tick1home=$6
mount --make-rprivate /
mount -t tmpfs tmpfs "$root"
mkdir -p "$root"/{usr,etc,proc,dev,tmp} "$root/home/p$uid"
# The jail's own /tmp first: tick1's installation may lie under the host's /tmp (a clone there), and
# is then mounted inside it, not hidden by it.
mount -t tmpfs -o mode=1777 tmpfs "$root/tmp"
mkdir -p "$root$tick1home"
for link in bin lib lib64 sbin ; do
    if [ -L "/$link" ] ; then ln -s "$(readlink "/$link")" "$root/$link" ; else mkdir "$root/$link" && mount --rbind "/$link" "$root/$link" ; fi
done
mount --rbind /usr "$root/usr"
mount --rbind /etc "$root/etc"
mount --rbind /dev "$root/dev"
mount --rbind "$tick1home" "$root$tick1home"
mount -t proc proc "$root/proc"
mount --bind "$home" "$root/home/p$uid"
env="env -i HOME=/home/p$uid PATH=/usr/bin:/bin TERM=xterm USER=p$uid VPL_LANG=en_US.UTF-8 TMPDIR=/tmp"
if [ "$mode" = pivot ] ; then
    cd "$root"
    mkdir .old
    pivot_root . .old
    cd /
    umount -l /.old
    rmdir /.old
    exec $env setpriv --reuid="$uid" --regid="$uid" --clear-groups --no-new-privs bash -c "$run"
fi
exec chroot "$root" $env setpriv --reuid="$uid" --regid="$uid" --clear-groups --no-new-privs bash -c "$run"
INSIDE
status=$?
rmdir "$root" 2>/dev/null
exit $status
