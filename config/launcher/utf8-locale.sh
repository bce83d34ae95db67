# tick1: Java names files in the locale's character set, and under the POSIX locale (a fresh
# Debian's login, a container with no LANG) a submission named "Zoë" could not be read. A locale
# that is not UTF-8 gives way to C.UTF-8, which every current glibc has built in.
case "${LC_ALL:-${LC_CTYPE:-${LANG:-}}}" in
    *[Uu][Tt][Ff]-8*|*[Uu][Tt][Ff]8*) ;;
    *) LC_ALL=C.UTF-8 ; export LC_ALL ;;
esac
