!> Text files written atomically: lines go to a temporary file beside the target, which is
!> renamed over the target only by `commit`. A run that fails never leaves a listing that
!> looks finished (design.md, "Files are written to a temporary name and renamed").
module atomic_file
    use kinds, only: i4
    use status, only: status_t, set_error, STATUS_IO_ERROR
    implicit none
    private

    type, public :: atomic_file_t
        character(len=:), allocatable :: path       !< final name
        character(len=:), allocatable :: temp_path  !< where lines are written meanwhile
        integer(i4) :: unit = -1
    contains
        procedure :: is_open => atomic_file_is_open
        procedure :: write_line => atomic_file_write_line
        procedure :: commit => atomic_file_commit
        procedure :: discard => atomic_file_discard
    end type atomic_file_t

    public :: open_atomic, rename_file

contains

    !> Opens `path` for writing through a temporary file `path.partial`.
    !>  file : out, the open file
    !>  path : in, the final file name
    !>  st   : out, STATUS_IO_ERROR naming the path when it cannot be created
    subroutine open_atomic(file, path, st)
        type(atomic_file_t), intent(out) :: file
        character(len=*), intent(in) :: path
        type(status_t), intent(out) :: st
        integer :: ios
        character(len=256) :: msg
        file%path = path
        file%temp_path = path // '.partial'
        open (newunit=file%unit, file=file%temp_path, status='replace', action='write', &
              form='formatted', access='sequential', iostat=ios, iomsg=msg)
        if (ios /= 0) then
            file%unit = -1
            call set_error(st, STATUS_IO_ERROR, 'cannot create ' // path // ': ' // trim(msg) &
                           // ' (check that the output directory exists and is writable)')
        end if
    end subroutine open_atomic

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

    !> Closes the temporary file and renames it to the final name.
    subroutine atomic_file_commit(self, st)
        class(atomic_file_t), intent(inout) :: self
        type(status_t), intent(out) :: st
        integer :: ios
        if (self%unit == -1) return
        close (self%unit, iostat=ios)
        self%unit = -1
        if (ios == 0) call rename_file(self%temp_path, self%path, ios)
        if (ios /= 0) call set_error(st, STATUS_IO_ERROR, 'cannot write ' // self%path)
    end subroutine atomic_file_commit

    !> Closes and deletes the temporary file: the final name is left untouched.
    subroutine atomic_file_discard(self)
        class(atomic_file_t), intent(inout) :: self
        integer :: ios
        if (self%unit == -1) return
        close (self%unit, status='delete', iostat=ios)
        self%unit = -1
    end subroutine atomic_file_discard

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
