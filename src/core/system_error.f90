!> The operating system's own words for a failed system call: errno and strerror of the C
!> library (glibc), so that messages give the real reason ("No such file or directory",
!> "Permission denied") rather than a generic "cannot write".
module system_error
    use, intrinsic :: iso_c_binding, only: c_int, c_long, c_ptr, c_char, c_size_t, &
        c_associated, c_f_pointer, c_int16_t
    implicit none
    private
    public :: last_errno, clear_errno, errno_text, process_id, readable_errno, c_text, path_kind, &
        folder_of, canonical_path, make_folder

    !> What a path names (path_kind).
    integer, parameter, public :: PATH_MISSING = 0   !< nothing (or it cannot be looked at)
    integer, parameter, public :: PATH_FILE = 1      !< a regular file
    integer, parameter, public :: PATH_FOLDER = 2    !< a directory
    integer, parameter, public :: PATH_DEVICE = 3    !< a device, FIFO or socket

    interface
        function c_errno_location() result(p) bind(c, name='__errno_location')
            import :: c_ptr
            type(c_ptr) :: p
        end function c_errno_location
        function c_strerror(code) result(text) bind(c, name='strerror')
            import :: c_int, c_ptr
            integer(c_int), value :: code
            type(c_ptr) :: text
        end function c_strerror
        function c_strlen(s) result(n) bind(c, name='strlen')
            import :: c_ptr, c_size_t
            type(c_ptr), value :: s
            integer(c_size_t) :: n
        end function c_strlen
        function c_getpid() result(pid) bind(c, name='getpid')
            import :: c_int
            integer(c_int) :: pid
        end function c_getpid
        function c_open(pathname, flags) result(fd) bind(c, name='open')
            import :: c_int, c_char
            character(kind=c_char), intent(in) :: pathname(*)
            integer(c_int), value :: flags
            integer(c_int) :: fd
        end function c_open
        function c_read(fd, buf, count) result(n) bind(c, name='read')
            import :: c_int, c_char, c_size_t, c_long
            integer(c_int), value :: fd
            character(kind=c_char), intent(out) :: buf(*)
            integer(c_size_t), value :: count
            integer(c_long) :: n                   ! ssize_t
        end function c_read
        function c_statx(dirfd, pathname, flags, mask, buf) result(rc) bind(c, name='statx')
            import :: c_int, c_char, c_int16_t
            integer(c_int), value :: dirfd, flags, mask
            character(kind=c_char), intent(in) :: pathname(*)
            integer(c_int16_t), intent(out) :: buf(*)
            integer(c_int) :: rc
        end function c_statx
        function c_mkdir(path, mode) result(rc) bind(c, name='mkdir')
            import :: c_char, c_int
            character(kind=c_char), intent(in) :: path(*)
            integer(c_int), value :: mode
            integer(c_int) :: rc
        end function c_mkdir
        function c_realpath(path, resolved) result(p) bind(c, name='realpath')
            import :: c_char, c_ptr
            character(kind=c_char), intent(in) :: path(*)
            type(c_ptr), value :: resolved
            type(c_ptr) :: p
        end function c_realpath
        subroutine c_free(p) bind(c, name='free')
            import :: c_ptr
            type(c_ptr), value :: p
        end subroutine c_free
        function c_close(fd) result(rc) bind(c, name='close')
            import :: c_int
            integer(c_int), value :: fd
            integer(c_int) :: rc
        end function c_close
    end interface

contains

    !> errno of the calling thread (read it right after the failed call).
    integer function last_errno()
        integer(c_int), pointer :: code
        call c_f_pointer(c_errno_location(), code)
        last_errno = int(code)
    end function last_errno

    !> Sets errno to 0, so that a library that fails without saying why can be told from one
    !> whose failure came from a system call (errno set).
    subroutine clear_errno()
        integer(c_int), pointer :: code
        call c_f_pointer(c_errno_location(), code)
        code = 0
    end subroutine clear_errno

    !> strerror(code): the system's text for an errno value.
    function errno_text(code) result(text)
        integer, intent(in) :: code
        character(len=:), allocatable :: text
        type(c_ptr) :: p
        p = c_strerror(int(code, c_int))
        if (.not. c_associated(p)) then
            text = 'system error'
            return
        end if
        text = c_text(p)
    end function errno_text

    !> The NUL-terminated C string at `p` as Fortran text ('' for a null pointer).
    function c_text(p) result(text)
        type(c_ptr), intent(in) :: p
        character(len=:), allocatable :: text
        character(kind=c_char), pointer :: chars(:)
        integer :: n, k
        text = ''
        if (.not. c_associated(p)) return
        n = int(c_strlen(p))
        call c_f_pointer(p, chars, [n])
        text = repeat(' ', n)
        do k = 1, n
            text(k:k) = chars(k)
        end do
    end function c_text

    !> 0 when `path` can be opened and read, else the errno of the failing call (open(2)
    !> read-only, then a read(2) of one byte: a folder opens but fails with EISDIR).
    integer function readable_errno(path) result(code)
        use, intrinsic :: iso_c_binding, only: c_null_char
        character(len=*), intent(in) :: path
        integer(c_int), parameter :: O_RDONLY = 0_c_int
        integer(c_int) :: fd, rc
        integer(c_long) :: n
        character(kind=c_char) :: buf(1)
        code = 0
        fd = c_open(path // c_null_char, O_RDONLY)
        if (fd < 0) then
            code = last_errno()
            return
        end if
        n = c_read(fd, buf, 1_c_size_t)
        if (n < 0_c_long) code = last_errno()
        rc = c_close(fd)
    end function readable_errno

    !> What `path` names, symbolic links followed: PATH_MISSING, PATH_FILE, PATH_FOLDER or
    !> PATH_DEVICE. statx(2), whose struct is the same on every architecture (the mode is
    !> the 16-bit word at byte 28, linux/stat.h).
    integer function path_kind(path) result(kind)
        use, intrinsic :: iso_c_binding, only: c_null_char
        character(len=*), intent(in) :: path
        integer(c_int), parameter :: AT_FDCWD = -100, STATX_TYPE = 1
        integer, parameter :: S_IFMT = int(o'170000'), S_IFREG = int(o'100000'), &
            S_IFDIR = int(o'040000')
        integer(c_int16_t) :: buf(128)      ! struct statx: 256 bytes
        integer :: mode
        kind = PATH_MISSING
        buf = 0
        if (c_statx(AT_FDCWD, path // c_null_char, 0_c_int, STATX_TYPE, buf) /= 0) return
        mode = iand(int(buf(15)), int(z'FFFF'))
        select case (iand(mode, S_IFMT))
        case (S_IFREG)
            kind = PATH_FILE
        case (S_IFDIR)
            kind = PATH_FOLDER
        case default
            kind = PATH_DEVICE
        end select
    end function path_kind

    !> The folder part of a path: 'a/b' for 'a/b/c', '/' for '/c', '.' for 'c'.
    pure function folder_of(path) result(folder)
        character(len=*), intent(in) :: path
        character(len=:), allocatable :: folder
        integer :: slash
        slash = index(path, '/', back=.true.)
        if (slash == 0) then
            folder = '.'
        else if (slash == 1) then
            folder = '/'
        else
            folder = path(1:slash - 1)
        end if
    end function folder_of

    !> The path with its folder resolved (realpath(3): absolute, no '.', '..' or symbolic
    !> links), so that two spellings of one file compare equal; the path as given when its
    !> folder cannot be resolved. The file itself need not exist.
    function canonical_path(path) result(canonical)
        use, intrinsic :: iso_c_binding, only: c_null_char, c_null_ptr
        character(len=*), intent(in) :: path
        character(len=:), allocatable :: canonical
        type(c_ptr) :: p
        canonical = path
        p = c_realpath(folder_of(path) // c_null_char, c_null_ptr)
        if (.not. c_associated(p)) return
        canonical = c_text(p) // '/' // path(index(path, '/', back=.true.) + 1:)
        call c_free(p)
    end function canonical_path

    !> Makes folder `path` (mode 0777 less the umask) unless it exists; returns 0 or the
    !> errno of mkdir(2) (EEXIST for an existing folder counts as success).
    integer function make_folder(path) result(code)
        use, intrinsic :: iso_c_binding, only: c_null_char
        character(len=*), intent(in) :: path
        integer, parameter :: EEXIST = 17
        code = 0
        if (c_mkdir(path // c_null_char, int(o'777', c_int)) == 0) return
        code = last_errno()
        if (code /= EEXIST) return
        if (path_kind(path) == PATH_FOLDER) code = 0
    end function make_folder

    !> The process identifier (getpid), e.g. to make temporary names unique per process.
    integer function process_id()
        process_id = int(c_getpid())
    end function process_id

end module system_error
