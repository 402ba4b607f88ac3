!> MED files of version 2.x (Code_Aster's older meshes, MED 2.3.6) read through MED's own
!> converter: the MED library's MEDimport (libmedimport, Debian package libmedimport0v5)
!> writes a copy of the file in the current version, which the MED server then reads. The copy
!> is private and temporary: a folder of its own made by the parent (make_import_folder), in
!> which the server links the file (`in.med`) and has MEDimport write `out.med`; the parent
!> removes both and the folder once the server has opened the copy, or died trying
!> (remove_import_folder), so nothing is left whatever happens (doc/stability.md, "Faults").
!>
!> MEDimport runs in the MED server (med_server), never in parasol's process: it copies the
!> file with a shell `cp` and calls exit() on some failures, and a damaged 2.x file is as
!> likely to crash it as HDF5. Its progress report goes to standard output: the server's
!> standard output is /dev/null from then on. The names handed to it are the folder's own
!> (`in.med`, `out.med` in a folder of safe characters), since it quotes them into a shell
!> command line: the user's file name never reaches the shell.
module med_import
    use, intrinsic :: iso_c_binding, only: c_int, c_long, c_char, c_null_char, c_ptr, &
        c_funptr, c_associated, c_f_procpointer
    use status, only: status_t, set_error, STATUS_IO_ERROR
    use kinds, only: i8
    use strings, only: to_text
    use system_error, only: last_errno, errno_text, canonical_path
    use dynamic_library, only: dynamic_library_t, open_library, find_symbol
    implicit none
    private

    public :: make_import_folder, remove_import_folder, convert_to_current, import_copy_path
    public :: IMPORT_TIME_BASE

    !> Limits of one conversion (MEDimport loops on some damaged files, writing its copy
    !> without end: 9.7 GB in 10 s for one of the fuzzer's cases): the copy may grow to
    !> IMPORT_SIZE_FACTOR times the file, at least IMPORT_SIZE_MIN bytes (a converted
    !> Code_Aster mesh is about 1.5 times its file), and the conversion may take
    !> IMPORT_TIME_BASE seconds plus one per MB of the file (Code_Aster's 2.x meshes convert
    !> in well under a second). Past either, the server stops: SIGALRM, or a write failing
    !> with EFBIG (SIGXFSZ is ignored, as in parasol).
    integer, parameter :: IMPORT_SIZE_FACTOR = 16, IMPORT_TIME_BASE = 60
    integer(c_long), parameter :: IMPORT_SIZE_MIN = 64_c_long * 1024 * 1024
    !> The converter's library (its soname: Debian ships no development link for it).
    character(len=*), parameter, public :: MEDIMPORT_LIBRARY = 'libmedimport.so.0'
    !> convert_to_current's own failures (MEDimport's are its med_err, < 0 too).
    integer(c_int), parameter, public :: IMPORT_NO_CONVERTER = -900201, &
        IMPORT_LINK_FAILED = -900202

    interface
        function c_mkdtemp(template) result(p) bind(c, name='mkdtemp')
            import :: c_char, c_ptr
            character(kind=c_char), intent(inout) :: template(*)
            type(c_ptr) :: p
        end function c_mkdtemp
        function c_symlink(target, linkpath) result(rc) bind(c, name='symlink')
            import :: c_char, c_int
            character(kind=c_char), intent(in) :: target(*), linkpath(*)
            integer(c_int) :: rc
        end function c_symlink
        function c_unlink(pathname) result(rc) bind(c, name='unlink')
            import :: c_char, c_int
            character(kind=c_char), intent(in) :: pathname(*)
            integer(c_int) :: rc
        end function c_unlink
        function c_rmdir(pathname) result(rc) bind(c, name='rmdir')
            import :: c_char, c_int
            character(kind=c_char), intent(in) :: pathname(*)
            integer(c_int) :: rc
        end function c_rmdir
        function c_open(pathname, flags) result(fd) bind(c, name='open')
            import :: c_char, c_int
            character(kind=c_char), intent(in) :: pathname(*)
            integer(c_int), value :: flags
            integer(c_int) :: fd
        end function c_open
        function c_dup2(old, new) result(fd) bind(c, name='dup2')
            import :: c_int
            integer(c_int), value :: old, new
            integer(c_int) :: fd
        end function c_dup2
        function c_close(fd) result(rc) bind(c, name='close')
            import :: c_int
            integer(c_int), value :: fd
            integer(c_int) :: rc
        end function c_close
        function c_alarm(seconds) result(left) bind(c, name='alarm')
            import :: c_int
            integer(c_int), value :: seconds
            integer(c_int) :: left
        end function c_alarm
        function c_setrlimit(resource, limits) result(rc) bind(c, name='setrlimit')
            import :: c_int, c_long
            integer(c_int), value :: resource
            integer(c_long), intent(in) :: limits(2)
            integer(c_int) :: rc
        end function c_setrlimit
        function c_getrlimit(resource, limits) result(rc) bind(c, name='getrlimit')
            import :: c_int, c_long
            integer(c_int), value :: resource
            integer(c_long), intent(out) :: limits(2)
            integer(c_int) :: rc
        end function c_getrlimit
        !> med_err MEDimport(const char *filein, const char *fileout) (MED 4 medimport.h)
        function medimport_f(filein, fileout) result(rc) bind(c)
            import :: c_char, c_int
            character(kind=c_char), intent(in) :: filein(*), fileout(*)
            integer(c_int) :: rc
        end function medimport_f
    end interface

contains

    !> Makes the private folder of one conversion: `$TMPDIR/parasol-medimport-XXXXXX`
    !> (mkdtemp(3): mode 0700), in /tmp when TMPDIR is unset or holds a character a shell
    !> would read (MEDimport quotes the names into a command line).
    !>  st : out, STATUS_IO_ERROR with the system's reason
    subroutine make_import_folder(folder, st)
        character(len=:), allocatable, intent(out) :: folder
        type(status_t), intent(out) :: st
        character(len=4096) :: tmp
        character(kind=c_char), allocatable :: template(:)
        character(len=:), allocatable :: base
        integer :: n, k, env_status
        type(c_ptr) :: p
        call get_environment_variable('TMPDIR', tmp, n, env_status)
        base = '/tmp'
        if (env_status == 0 .and. n > 0) then
            if (verify(tmp(1:n), 'abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ' // &
                '0123456789/._+-') == 0) base = tmp(1:n)
        end if
        folder = base // '/parasol-medimport-XXXXXX'
        n = len(folder)
        allocate (template(n + 1))
        do k = 1, n
            template(k) = folder(k:k)
        end do
        template(n + 1) = c_null_char
        p = c_mkdtemp(template)
        if (.not. c_associated(p)) then
            call set_error(st, STATUS_IO_ERROR, 'cannot make a temporary folder in ' // base &
                // ' for the conversion: ' // errno_text(last_errno()))
            return
        end if
        do k = 1, n
            folder(k:k) = template(k)
        end do
    end subroutine make_import_folder

    !> The converted copy in `folder`.
    function import_copy_path(folder) result(path)
        character(len=*), intent(in) :: folder
        character(len=:), allocatable :: path
        path = folder // '/out.med'
    end function import_copy_path

    !> Removes the folder of a conversion and what is in it (a file open in the server stays
    !> readable there until it closes it). Does nothing for ''.
    subroutine remove_import_folder(folder)
        character(len=*), intent(in) :: folder
        integer(c_int) :: rc
        if (len(folder) == 0) return
        rc = c_unlink(folder // '/in.med' // c_null_char)
        rc = c_unlink(folder // '/out.med' // c_null_char)
        rc = c_rmdir(folder // c_null_char)
    end subroutine remove_import_folder

    !> In the MED server: converts MED file `path` (version 2.x) to import_copy_path(folder)
    !> with MEDimport. Returns >= 0 on success; IMPORT_NO_CONVERTER when libmedimport cannot
    !> be loaded (why: `reason`), IMPORT_LINK_FAILED (errno kept) when the file cannot be
    !> linked into the folder, else MEDimport's own result (< 0: it could not convert).
    integer(c_int) function convert_to_current(path, folder, reason) result(rc)
        character(len=*), intent(in) :: path, folder
        character(len=:), allocatable, intent(out) :: reason
        integer(c_int), parameter :: O_WRONLY = 1, STDOUT = 1
        type(dynamic_library_t) :: lib
        type(status_t) :: st
        type(c_funptr) :: address
        procedure(medimport_f), pointer :: medimport
        integer(c_int) :: null, ignored
        integer(c_int), parameter :: RLIMIT_FSIZE = 1
        integer, parameter :: EFBIG = 27
        integer(c_long) :: saved(2), limits(2)
        integer(i8) :: size_bytes
        integer :: err
        logical :: have_limits
        reason = ''
        limits = 0
        null = c_open('/dev/null' // c_null_char, O_WRONLY)
        if (null >= 0) then
            ignored = c_dup2(null, STDOUT)
            ignored = c_close(null)
        end if
        if (c_symlink(canonical_path(path) // c_null_char, folder // '/in.med' // &
                      c_null_char) /= 0) then
            rc = IMPORT_LINK_FAILED
            reason = errno_text(last_errno())
            return
        end if
        call open_library(lib, MEDIMPORT_LIBRARY, st)
        if (st%ok()) call find_symbol(lib, 'MEDimport', address, st)
        if (st%failed()) then
            rc = IMPORT_NO_CONVERTER
            reason = st%message // ' (MED''s converter: Debian package libmedimport0v5)'
            return
        end if
        call c_f_procpointer(address, medimport)
        size_bytes = 0
        inquire (file=path, size=size_bytes)
        size_bytes = max(size_bytes, 0_i8)
        have_limits = c_getrlimit(RLIMIT_FSIZE, saved) == 0
        if (have_limits) then
            limits = saved
            limits(1) = max(IMPORT_SIZE_MIN, int(IMPORT_SIZE_FACTOR, c_long) * size_bytes)
            if (saved(2) >= 0) limits(1) = min(limits(1), saved(2))  ! -1: RLIM_INFINITY
            ignored = c_setrlimit(RLIMIT_FSIZE, limits)
        end if
        ignored = c_alarm(int(min(IMPORT_TIME_BASE + size_bytes / 1000000_i8, 86400_i8), &
                              c_int))
        rc = medimport(folder // '/in.med' // c_null_char, folder // '/out.med' // c_null_char)
        err = last_errno()
        ignored = c_alarm(0_c_int)
        if (have_limits) ignored = c_setrlimit(RLIMIT_FSIZE, saved)
        if (rc < 0) then
            reason = 'MEDimport failed (MED error ' // to_text(int(rc)) // ')'
            if (err == EFBIG) reason = 'MEDimport''s copy grew past ' // &
                to_text(int(limits(1) / 1048576)) // ' MB (' // to_text(IMPORT_SIZE_FACTOR) &
                // ' times the file): it is damaged'
        end if
    end function convert_to_current

end module med_import
