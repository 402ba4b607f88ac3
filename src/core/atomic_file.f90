!> Every file parasol writes goes through this module (doc/architecture.md, "Output files"):
!> lines go to a temporary file beside the target, `<path>.<pid>.partial`, which takes the
!> final name only at `commit`, and only when every byte was handed to the system and the
!> file was closed without error. A run that fails, a full disk or an interrupted run never
!> leaves a missing, empty or truncated file under a final name, and the previous file of
!> that name stays as it was (design.md, "Files are written to a temporary name and
!> renamed").
!>
!> Writing is done with the system calls (creat, write, close) on a buffer of our own rather
!> than with Fortran units, so that every failure comes with the system's errno: the first
!> failed write (ENOSPC, EFBIG, EIO, EDQUOT, ...) is remembered, later writes are dropped,
!> and `commit` reports it as "cannot write PATH: No space left on device" and removes the
!> temporary file. A failed close is a failed write (NFS and some file systems report the
!> lost data only there).
!>
!> Files that a library writes itself (MED through HDF5) use the same protocol through
!> `temporary_path`, `track_temporary` and `publish_file`.
!>
!> Temporary files still open are removed when the process is interrupted (SIGINT, SIGTERM,
!> SIGHUP: `install_interrupt_cleanup`), so that an interrupted run leaves the earlier
!> listings and no `.partial` file behind; SIGXFSZ (a file size limit, `ulimit -f`) is
!> ignored so that the write fails with EFBIG and is reported like a full disk.
module atomic_file
    use, intrinsic :: iso_c_binding, only: c_int, c_char, c_long, c_size_t, c_null_char, &
        c_funptr, c_funloc, c_intptr_t
    use kinds, only: i4, i8
    use status, only: status_t, set_error, STATUS_IO_ERROR
    use strings, only: to_text
    use system_error, only: last_errno, errno_text, process_id, path_kind, folder_of, &
        PATH_FOLDER, PATH_DEVICE
    implicit none
    private

    !> Bytes gathered before they are handed to write(2) (lines longer go out directly).
    integer, parameter :: BUFFER_BYTES = 65536
    !> errno values the module tests (Linux, asm-generic/errno-base.h).
    integer, parameter :: EINTR = 4, EIO = 5, ENOENT = 2, EACCES = 13, ENOTDIR = 20, &
        EROFS = 30

    !> What stays with an open file between calls. Held through a pointer so that a file
    !> handed down as `intent(in)` (as a Fortran unit number would be) can still be written.
    type :: file_state_t
        integer(c_int) :: fd = -1
        character(len=:), allocatable :: buffer   !< BUFFER_BYTES long
        integer :: used = 0                       !< bytes of `buffer` waiting
        integer :: error = 0                      !< errno of the first failure, 0 = none
        logical :: direct = .false.               !< written in place (a device, a FIFO)
    end type file_state_t

    type, public :: atomic_file_t
        character(len=:), allocatable :: path       !< final name
        character(len=:), allocatable :: temp_path  !< where lines are written meanwhile
        type(file_state_t), pointer, private :: state => null()
    contains
        procedure :: is_open => atomic_file_is_open
        procedure :: failed => atomic_file_failed
        procedure :: error_message => atomic_file_error_message
        procedure :: write_line => atomic_file_write_line
        procedure :: write_text => atomic_file_write_text
        procedure :: flush => atomic_file_flush
        procedure :: commit => atomic_file_commit
        procedure :: discard => atomic_file_discard
    end type atomic_file_t

    public :: open_atomic, rename_file, delete_file, temporary_path, publish_file, &
        track_temporary, untrack_temporary, install_interrupt_cleanup, write_failure_text, &
        scratch_path, copy_file

    ! ---- temporary files removed on an interrupt (see install_interrupt_cleanup) ----
    !> Temporary files tracked at once (a run has a handful open: .mess, .resu, one result).
    integer, parameter :: MAX_TRACKED = 64
    !> Longest tracked path, in bytes (PATH_MAX of Linux).
    integer, parameter :: MAX_PATH_BYTES = 4096
    character(kind=c_char), save, volatile :: tracked_paths(MAX_PATH_BYTES, MAX_TRACKED)
    logical, save, volatile :: tracked(MAX_TRACKED) = .false.

    integer(c_int), parameter :: SIGHUP = 1, SIGINT = 2, SIGTERM = 15, SIGXFSZ = 25

    interface
        function c_creat(pathname, mode) result(fd) bind(c, name='creat')
            import :: c_int, c_char
            character(kind=c_char), intent(in) :: pathname(*)
            integer(c_int), value :: mode
            integer(c_int) :: fd
        end function c_creat
        function c_open(pathname, flags) result(fd) bind(c, name='open')
            import :: c_int, c_char
            character(kind=c_char), intent(in) :: pathname(*)
            integer(c_int), value :: flags
            integer(c_int) :: fd
        end function c_open
        function c_write(fd, buf, count) result(n) bind(c, name='write')
            import :: c_int, c_char, c_size_t, c_long
            integer(c_int), value :: fd
            character(kind=c_char), intent(in) :: buf(*)
            integer(c_size_t), value :: count
            integer(c_long) :: n                   ! ssize_t
        end function c_write
        function c_close(fd) result(rc) bind(c, name='close')
            import :: c_int
            integer(c_int), value :: fd
            integer(c_int) :: rc
        end function c_close
        function c_rmdir(pathname) result(rc) bind(c, name='rmdir')
            import :: c_char, c_int
            character(kind=c_char), intent(in) :: pathname(*)
            integer(c_int) :: rc
        end function c_rmdir
        function c_unlink(pathname) result(rc) bind(c, name='unlink')
            import :: c_int, c_char
            character(kind=c_char), intent(in) :: pathname(*)
            integer(c_int) :: rc
        end function c_unlink
        function c_rename(old, new) result(rc) bind(c, name='rename')
            import :: c_int, c_char
            character(kind=c_char), intent(in) :: old(*), new(*)
            integer(c_int) :: rc
        end function c_rename
        function c_signal(signum, handler) result(previous) bind(c, name='signal')
            import :: c_int, c_funptr
            integer(c_int), value :: signum
            type(c_funptr), value :: handler
            type(c_funptr) :: previous
        end function c_signal
        function c_raise(sig) result(rc) bind(c, name='raise')
            import :: c_int
            integer(c_int), value :: sig
            integer(c_int) :: rc
        end function c_raise
    end interface

contains

    !> Opens `path` for writing through a temporary file beside it, `path.<pid>.partial`
    !> (unique per process, so that two runs writing into one folder never share it).
    !> A path that names a device or a FIFO (/dev/stdout, /dev/full, a named pipe; or a
    !> symbolic link to one) is written in place: a device has no temporary name to take,
    !> and renaming over it would replace it by a file.
    !>  file : out, the open file
    !>  path : in, the final file name
    !>  st   : out, STATUS_IO_ERROR naming the path (never the temporary name) and the
    !>         system's reason, e.g. "No such file or directory" for a missing folder, or
    !>         that the path is a folder
    subroutine open_atomic(file, path, st)
        type(atomic_file_t), intent(out) :: file
        character(len=*), intent(in) :: path
        type(status_t), intent(out) :: st
        call open_file(file, path, .false., st)
    end subroutine open_atomic

    ! open_atomic, or with in_place = .true. a file written under its own name (a temporary
    ! of ours, a device): commit then only closes it.
    subroutine open_file(file, path, in_place, st)
        type(atomic_file_t), intent(out) :: file
        character(len=*), intent(in) :: path
        logical, intent(in) :: in_place
        type(status_t), intent(out) :: st
        integer(c_int), parameter :: MODE_RW_R_R = int(o'644', c_int), O_WRONLY = 1
        integer(c_int) :: fd
        integer :: code, kind
        logical :: direct
        file%path = path
        kind = path_kind(path)
        if (kind == PATH_FOLDER) then
            call set_error(st, STATUS_IO_ERROR, 'cannot write ' // path // ': it is a ' // &
                'folder (a file name is needed here)')
            return
        end if
        direct = kind == PATH_DEVICE .or. in_place
        if (kind == PATH_DEVICE) then
            file%temp_path = path
            fd = c_open(path // c_null_char, O_WRONLY)
        else if (in_place) then
            file%temp_path = path
            fd = c_creat(path // c_null_char, MODE_RW_R_R)
        else
            file%temp_path = temporary_path(path)
            fd = c_creat(file%temp_path // c_null_char, MODE_RW_R_R)
        end if
        if (fd < 0) then
            code = last_errno()
            call set_error(st, STATUS_IO_ERROR, 'cannot create ' // path // ': ' // &
                errno_text(code) // folder_hint(code, path))
            return
        end if
        if (.not. direct) call track_temporary(file%temp_path)
        allocate (file%state)
        file%state%fd = fd
        file%state%direct = direct
        allocate (character(len=BUFFER_BYTES) :: file%state%buffer)
    end subroutine open_file

    !> The temporary name under which `path` is written: `path.<pid>.partial`.
    function temporary_path(path) result(temp)
        character(len=*), intent(in) :: path
        character(len=:), allocatable :: temp
        temp = path // '.' // to_text(int(process_id(), i4)) // '.partial'
    end function temporary_path

    !> A temporary name for a file a library writes whole before it is copied to `path`, a
    !> device (a library cannot write a device itself: HDF5 seeks): in $TMPDIR (else /tmp),
    !> `parasol.<pid>.<n>.<file name>.partial`, n counting the names given.
    function scratch_path(path) result(temp)
        character(len=*), intent(in) :: path
        character(len=:), allocatable :: temp, folder
        integer, save :: given = 0
        integer :: n, ios
        character(len=4096) :: value
        given = given + 1
        call get_environment_variable('TMPDIR', value, n, ios)
        folder = '/tmp'
        if (ios == 0 .and. n > 0) folder = value(1:n)
        temp = folder // '/parasol.' // to_text(int(process_id(), i4)) // '.' // &
            to_text(int(given, i4)) // '.' // path(index(path, '/', back=.true.) + 1:) // &
            '.partial'
    end function scratch_path

    !> Copies file `from` into `to` with checked writes: `to` is written in place (it is a
    !> temporary file of ours, or a device), created if needed.
    !>  label : in, the file messages name (the final name the user gave)
    !>  st    : out, STATUS_IO_ERROR "cannot read FROM: ..." or "cannot write LABEL: <reason>"
    subroutine copy_file(from, to, label, st)
        character(len=*), intent(in) :: from, to, label
        type(status_t), intent(out) :: st
        integer, parameter :: CHUNK = 1048576
        type(atomic_file_t) :: out
        character(len=:), allocatable :: bytes
        integer(i8) :: size_bytes, done
        integer :: in, ios, n
        character(len=256) :: msg
        open (newunit=in, file=from, access='stream', form='unformatted', status='old', &
              action='read', iostat=ios, iomsg=msg)
        if (ios /= 0) then
            call set_error(st, STATUS_IO_ERROR, 'cannot read ' // from // ': ' // trim(msg))
            return
        end if
        inquire (unit=in, size=size_bytes)
        call open_file(out, to, .true., st)
        if (st%failed()) then
            close (in)
            call set_error(st, STATUS_IO_ERROR, 'cannot write ' // label // ': ' // st%message)
            return
        end if
        out%path = label
        allocate (character(len=CHUNK) :: bytes)
        done = 0
        do while (done < size_bytes)
            n = int(min(int(CHUNK, i8), size_bytes - done))
            read (in, iostat=ios, iomsg=msg) bytes(1:n)
            if (ios /= 0) exit
            call out%write_text(bytes(1:n))
            done = done + n
        end do
        close (in)
        if (ios /= 0) then
            call out%discard()
            call set_error(st, STATUS_IO_ERROR, 'cannot read ' // from // ': ' // trim(msg))
            return
        end if
        call out%commit(st)
    end subroutine copy_file

    !> What to check for the usual errno values of a file creation: the folder named (it
    !> may be a folder of the deck's own, DEFI_FICHIER(FICHIER='sub/x.txt'), not the output
    !> folder; cli says "--outdir" for the listings).
    function folder_hint(code, path) result(text)
        integer, intent(in) :: code
        character(len=*), intent(in) :: path
        character(len=:), allocatable :: text
        select case (code)
        case (ENOENT, ENOTDIR)
            text = ' (its folder ' // folder_of(path) // ' does not exist)'
        case (EACCES, EROFS)
            text = ' (its folder ' // folder_of(path) // ' must be writable)'
        case default
            text = ''
        end select
    end function folder_hint

    logical function atomic_file_is_open(self)
        class(atomic_file_t), intent(in) :: self
        atomic_file_is_open = associated(self%state)
    end function atomic_file_is_open

    !> True once a write to the file has failed (the file will not be published).
    logical function atomic_file_failed(self)
        class(atomic_file_t), intent(in) :: self
        atomic_file_failed = .false.
        if (associated(self%state)) atomic_file_failed = self%state%error /= 0
    end function atomic_file_failed

    !> "cannot write PATH: <the system's reason>" for a file whose write failed ('' if none).
    function atomic_file_error_message(self) result(text)
        class(atomic_file_t), intent(in) :: self
        character(len=:), allocatable :: text
        text = ''
        if (.not. self%failed()) return
        text = write_failure_text(self%path, self%state%error)
    end function atomic_file_error_message

    !> The message of a write that failed with errno `code`, naming the final file:
    !> "cannot write OUT/plate.resu: No space left on device".
    function write_failure_text(path, code) result(text)
        character(len=*), intent(in) :: path
        integer, intent(in) :: code
        character(len=:), allocatable :: text
        text = 'cannot write ' // path // ': ' // errno_text(code)
    end function write_failure_text

    !> Writes one line (no-op on a file that is not open or whose writing already failed).
    subroutine atomic_file_write_line(self, line)
        class(atomic_file_t), intent(in) :: self
        character(len=*), intent(in) :: line
        call self%write_text(line)
        call self%write_text(new_line('a'))
    end subroutine atomic_file_write_line

    !> Writes `text` as it is (no line end added).
    subroutine atomic_file_write_text(self, text)
        class(atomic_file_t), intent(in) :: self
        character(len=*), intent(in) :: text
        if (.not. associated(self%state)) return
        associate (s => self%state)
            if (s%error /= 0) return
            if (s%used + len(text) > BUFFER_BYTES) then
                call drain(s)
                if (s%error /= 0) return
            end if
            if (len(text) > BUFFER_BYTES) then
                call write_all(s, text)
            else
                s%buffer(s%used + 1:s%used + len(text)) = text
                s%used = s%used + len(text)
            end if
        end associate
    end subroutine atomic_file_write_text

    !> Hands the lines written so far to the system (the temporary file then shows them,
    !> e.g. to `tail -f`); the final name still appears only at commit. A failure is kept
    !> for commit (see `failed`).
    subroutine atomic_file_flush(self)
        class(atomic_file_t), intent(in) :: self
        if (.not. associated(self%state)) return
        call drain(self%state)
    end subroutine atomic_file_flush

    !> Writes the buffer out.
    subroutine drain(s)
        type(file_state_t), intent(inout) :: s
        if (s%error /= 0 .or. s%used == 0) return
        call write_all(s, s%buffer(1:s%used))
        s%used = 0
    end subroutine drain

    !> write(2) of all of `bytes`, going on after a partial write or an interrupted call;
    !> the first failure's errno is kept in s%error.
    subroutine write_all(s, bytes)
        type(file_state_t), intent(inout) :: s
        character(len=*), intent(in) :: bytes
        integer(c_long) :: n
        integer :: done, code
        done = 0
        do while (done < len(bytes))
            n = c_write(s%fd, bytes(done + 1:), int(len(bytes) - done, c_size_t))
            if (n < 0_c_long) then
                code = last_errno()
                if (code == EINTR) cycle
                s%error = code
                return
            else if (n == 0_c_long) then
                s%error = EIO      ! no progress on a regular file: report it, never spin
                return
            end if
            done = done + int(n)
        end do
    end subroutine write_all

    !> Writes what is left, closes the temporary file and renames it to the final name.
    !> Nothing is published when any write or the close failed: the temporary file is
    !> removed and the final name keeps its previous file (if any). A file that is not
    !> open commits as a no-op.
    !>  st : out, STATUS_IO_ERROR "cannot write PATH: <reason>"
    subroutine atomic_file_commit(self, st)
        class(atomic_file_t), intent(inout) :: self
        type(status_t), intent(out) :: st
        integer :: code
        logical :: direct
        if (.not. associated(self%state)) return
        call drain(self%state)
        code = self%state%error
        if (c_close(self%state%fd) /= 0 .and. code == 0) code = last_errno()
        direct = self%state%direct
        deallocate (self%state)
        if (code /= 0) then
            if (.not. direct) call remove_temporary(self%temp_path)
            call set_error(st, STATUS_IO_ERROR, write_failure_text(self%path, code))
            return
        end if
        if (.not. direct) call publish_file(self%temp_path, self%path, st)
    end subroutine atomic_file_commit

    !> Closes and deletes the temporary file: the final name is left untouched (a device
    !> written in place keeps what it was given).
    subroutine atomic_file_discard(self)
        class(atomic_file_t), intent(inout) :: self
        integer(c_int) :: rc
        logical :: direct
        if (.not. associated(self%state)) return
        rc = c_close(self%state%fd)
        direct = self%state%direct
        deallocate (self%state)
        if (.not. direct) call remove_temporary(self%temp_path)
    end subroutine atomic_file_discard

    !> Gives a complete temporary file its final name (rename(2), atomic on one file
    !> system); on failure the temporary file is removed.
    !>  st : out, STATUS_IO_ERROR "cannot write PATH: <reason>"
    subroutine publish_file(temp, path, st)
        character(len=*), intent(in) :: temp, path
        type(status_t), intent(out) :: st
        integer :: ios, code
        call rename_file(temp, path, ios)
        if (ios /= 0) then
            code = last_errno()
            call remove_temporary(temp)
            call set_error(st, STATUS_IO_ERROR, write_failure_text(path, code))
            return
        end if
        call untrack_temporary(temp)
    end subroutine publish_file

    !> Deletes a temporary file and forgets it.
    subroutine remove_temporary(temp)
        character(len=*), intent(in) :: temp
        call untrack_temporary(temp)
        call delete_file(temp)
    end subroutine remove_temporary

    !> Removes `path` (unlink(2)); a failure is ignored (the file may be gone already).
    subroutine delete_file(path)
        character(len=*), intent(in) :: path
        integer(c_int) :: rc
        rc = c_unlink(path // c_null_char)
    end subroutine delete_file

    !> rename(2) through the C library: atomic on one file system.
    !>  from, to : in, the paths;  ios : out, 0 on success (errno is then last_errno())
    subroutine rename_file(from, to, ios)
        character(len=*), intent(in) :: from, to
        integer, intent(out) :: ios
        ios = int(c_rename(from // c_null_char, to // c_null_char))
    end subroutine rename_file

    ! ---- interrupts ----

    !> Records a temporary file (or an empty-by-then folder of them, removed after the
    !> files) to remove if the process is interrupted before it is
    !> published or discarded (a path longer than MAX_PATH_BYTES, or more than MAX_TRACKED
    !> at once, is not tracked: the file then stays behind after an interrupt).
    subroutine track_temporary(temp)
        character(len=*), intent(in) :: temp
        integer :: k, i
        if (len(temp) >= MAX_PATH_BYTES) return
        do k = 1, MAX_TRACKED
            if (tracked(k)) cycle
            do i = 1, len(temp)
                tracked_paths(i, k) = temp(i:i)
            end do
            tracked_paths(len(temp) + 1, k) = c_null_char
            tracked(k) = .true.       ! set last: the handler sees a complete path
            return
        end do
    end subroutine track_temporary

    !> Forgets a temporary file (published, discarded or removed).
    subroutine untrack_temporary(temp)
        character(len=*), intent(in) :: temp
        integer :: k, i
        logical :: same
        do k = 1, MAX_TRACKED
            if (.not. tracked(k)) cycle
            if (len(temp) >= MAX_PATH_BYTES) cycle
            if (tracked_paths(len(temp) + 1, k) /= c_null_char) cycle
            same = .true.
            do i = 1, len(temp)
                if (tracked_paths(i, k) /= temp(i:i)) then
                    same = .false.
                    exit
                end if
            end do
            if (same) tracked(k) = .false.
        end do
    end subroutine untrack_temporary

    !> Makes SIGINT, SIGTERM and SIGHUP remove the tracked temporary files before the
    !> process ends as the signal says (the default action, so the parent sees the signal);
    !> ignores SIGXFSZ, so that exceeding a file size limit is a failed write (EFBIG).
    !> cli calls it once, before any file is opened.
    subroutine install_interrupt_cleanup()
        type(c_funptr) :: previous
        previous = c_signal(SIGINT, c_funloc(on_interrupt))
        previous = c_signal(SIGTERM, c_funloc(on_interrupt))
        previous = c_signal(SIGHUP, c_funloc(on_interrupt))
        previous = c_signal(SIGXFSZ, transfer(1_c_intptr_t, previous))    ! SIG_IGN
    end subroutine install_interrupt_cleanup

    !> The handler: unlink(2) and signal(2) and raise(3) only (async-signal-safe), on the
    !> tracked paths, which are complete C strings whenever their flag is set.
    subroutine on_interrupt(sig) bind(c)
        integer(c_int), value :: sig
        integer(c_int) :: rc
        type(c_funptr) :: previous
        integer :: k
        do k = 1, MAX_TRACKED
            if (tracked(k)) rc = c_unlink(tracked_paths(1, k))
        end do
        do k = 1, MAX_TRACKED        ! tracked folders (med_import's), empty by now
            if (tracked(k)) rc = c_rmdir(tracked_paths(1, k))
        end do
        previous = c_signal(sig, transfer(0_c_intptr_t, previous))           ! SIG_DFL
        rc = c_raise(sig)
    end subroutine on_interrupt

end module atomic_file
