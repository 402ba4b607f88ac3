!> Text files written atomically: lines go to a temporary file beside the target, which is
!> renamed over the target only by `commit`. A run that fails never leaves a listing that
!> looks finished (design.md, "Files are written to a temporary name and renamed").
module atomic_file
    use kinds, only: i4
    use status, only: status_t, set_error, STATUS_IO_ERROR
    use strings, only: to_text
    use system_error, only: last_errno, errno_text, process_id
    implicit none
    private

    type, public :: atomic_file_t
        character(len=:), allocatable :: path       !< final name
        character(len=:), allocatable :: temp_path  !< where lines are written meanwhile
        integer(i4) :: unit = -1
    contains
        procedure :: is_open => atomic_file_is_open
        procedure :: write_line => atomic_file_write_line
        procedure :: flush => atomic_file_flush
        procedure :: commit => atomic_file_commit
        procedure :: discard => atomic_file_discard
    end type atomic_file_t

    public :: open_atomic, rename_file, delete_file

contains

    !> Opens `path` for writing through a temporary file beside it, `path.<pid>.partial`
    !> (unique per process, so that two runs writing into one folder never share it).
    !>  file : out, the open file
    !>  path : in, the final file name
    !>  st   : out, STATUS_IO_ERROR naming the path (never the temporary name) and the
    !>         system's reason, e.g. "No such file or directory" for a missing folder
    subroutine open_atomic(file, path, st)
        type(atomic_file_t), intent(out) :: file
        character(len=*), intent(in) :: path
        type(status_t), intent(out) :: st
        integer :: ios, code
        file%path = path
        file%temp_path = path // '.' // to_text(int(process_id(), i4)) // '.partial'
        ! create it with open(2) first: a failure then comes with errno, the system's reason
        code = create_file(file%temp_path)
        if (code /= 0) then
            call set_error(st, STATUS_IO_ERROR, 'cannot create ' // path // ': ' // &
                errno_text(code) // folder_hint(code))
            return
        end if
        open (newunit=file%unit, file=file%temp_path, status='replace', action='write', &
              form='formatted', access='sequential', iostat=ios)
        if (ios /= 0) then
            file%unit = -1
            call set_error(st, STATUS_IO_ERROR, 'cannot create ' // path // &
                ' (the file system refused to open it for writing)')
        end if
    end subroutine open_atomic

    !> What to check for the usual errno values of a file creation.
    function folder_hint(code) result(text)
        integer, intent(in) :: code
        character(len=:), allocatable :: text
        integer, parameter :: ENOENT = 2, EACCES = 13, ENOTDIR = 20, EROFS = 30
        select case (code)
        case (ENOENT, ENOTDIR)
            text = ' (the output folder must exist: create it or give another --outdir)'
        case (EACCES, EROFS)
            text = ' (the output folder must be writable)'
        case default
            text = ''
        end select
    end function folder_hint

    !> Creates (or truncates) `path` with open(2); returns 0 or errno.
    integer function create_file(path) result(code)
        use, intrinsic :: iso_c_binding, only: c_int, c_char, c_null_char
        character(len=*), intent(in) :: path
        interface
            integer(c_int) function c_creat(pathname, mode) bind(c, name='creat')
                import :: c_int, c_char
                character(kind=c_char), intent(in) :: pathname(*)
                integer(c_int), value :: mode
            end function c_creat
            integer(c_int) function c_close(fd) bind(c, name='close')
                import :: c_int
                integer(c_int), value :: fd
            end function c_close
        end interface
        integer(c_int) :: fd, rc
        integer(c_int), parameter :: MODE_RW_R_R = int(o'644', c_int)
        code = 0
        fd = c_creat(path // c_null_char, MODE_RW_R_R)
        if (fd < 0) then
            code = last_errno()
            return
        end if
        rc = c_close(fd)
    end function create_file

    logical function atomic_file_is_open(self)
        class(atomic_file_t), intent(in) :: self
        atomic_file_is_open = self%unit /= -1
    end function atomic_file_is_open

    !> Writes one line (no-op on a file that is not open).
    subroutine atomic_file_write_line(self, line)
        class(atomic_file_t), intent(in) :: self
        character(len=*), intent(in) :: line
        if (self%unit == -1) return
        write (self%unit, '(a)') line
    end subroutine atomic_file_write_line

    !> Hands the lines written so far to the system (the temporary file then shows them,
    !> e.g. to `tail -f`); the final name still appears only at commit.
    subroutine atomic_file_flush(self)
        class(atomic_file_t), intent(in) :: self
        if (self%unit == -1) return
        flush (self%unit)
    end subroutine atomic_file_flush

    !> Closes the temporary file and renames it to the final name.
    subroutine atomic_file_commit(self, st)
        class(atomic_file_t), intent(inout) :: self
        type(status_t), intent(out) :: st
        integer :: ios
        if (self%unit == -1) return
        close (self%unit, iostat=ios)
        self%unit = -1
        if (ios /= 0) then
            call delete_file(self%temp_path)
            call set_error(st, STATUS_IO_ERROR, 'cannot write ' // self%path // &
                ' (closing it failed: is the disk full?)')
            return
        end if
        call rename_file(self%temp_path, self%path, ios)
        if (ios /= 0) then
            ios = last_errno()
            call delete_file(self%temp_path)
            call set_error(st, STATUS_IO_ERROR, 'cannot write ' // self%path // ': ' // &
                errno_text(ios))
        end if
    end subroutine atomic_file_commit

    !> Closes and deletes the temporary file: the final name is left untouched.
    subroutine atomic_file_discard(self)
        class(atomic_file_t), intent(inout) :: self
        integer :: ios
        if (self%unit == -1) return
        close (self%unit, status='delete', iostat=ios)
        self%unit = -1
    end subroutine atomic_file_discard

    !> Removes `path` (unlink(2)); a failure is ignored (the file may be gone already).
    subroutine delete_file(path)
        use, intrinsic :: iso_c_binding, only: c_int, c_char, c_null_char
        character(len=*), intent(in) :: path
        interface
            integer(c_int) function c_unlink(pathname) bind(c, name='unlink')
                import :: c_int, c_char
                character(kind=c_char), intent(in) :: pathname(*)
            end function c_unlink
        end interface
        integer(c_int) :: rc
        rc = c_unlink(path // c_null_char)
    end subroutine delete_file

    !> rename(2) through the C library: atomic on one file system. Also used to commit files
    !> that a library writes itself under a temporary name (MED files, result_med).
    !>  from, to : in, the paths;  ios : out, 0 on success
    subroutine rename_file(from, to, ios)
        use, intrinsic :: iso_c_binding, only: c_int, c_char, c_null_char
        character(len=*), intent(in) :: from, to
        integer, intent(out) :: ios
        interface
            integer(c_int) function c_rename(old, new) bind(c, name='rename')
                import :: c_int, c_char
                character(kind=c_char), intent(in) :: old(*), new(*)
            end function c_rename
        end interface
        ios = int(c_rename(from // c_null_char, to // c_null_char))
    end subroutine rename_file

end module atomic_file
