!> Text written to a logical unit by IMPR_TABLE and IMPR_FONCTION, as Code_Aster writes to
!> its units: unit 8 is the result listing (the `.resu`); another unit goes to the file
!> bound to it (`--unit N=PATH`, or the export file's F line), else to `<stem>.<N>` in
!> the output folder (Code_Aster's own tests name their unit files <case>.<N>). A unit
!> written earlier in the run is added to, as Code_Aster appends to an open unit; the file
!> is rewritten atomically each time (atomic_file), so a failed run never leaves half a
!> table.
module unit_text_output
    use kinds, only: i4
    use strings, only: string_t, to_text
    use status, only: status_t, set_error, STATUS_IO_ERROR
    use atomic_file, only: atomic_file_t, open_atomic
    use run_context, only: run_context_t
    implicit none
    private

    !> Code_Aster's unit of the result listing (RESULTAT).
    integer, parameter, public :: RESULT_LISTING_UNIT = 8
    !> Longest line read back from a unit file written earlier in the run.
    integer, parameter :: CHUNK = 4096

    public :: write_unit_text, unit_file_path

contains

    !> The file of unit `unit` ('' for the result listing).
    function unit_file_path(ctx, unit) result(path)
        type(run_context_t), intent(in) :: ctx
        integer, intent(in) :: unit
        character(len=:), allocatable :: path
        type(status_t) :: st
        path = ''
        if (unit == RESULT_LISTING_UNIT) return
        if (allocated(ctx%unit_numbers)) then
            if (any(ctx%unit_numbers == unit)) then
                call ctx%unit_path(unit, 'TEXT', path, st)
                if (st%ok()) return
            end if
        end if
        path = ctx%output_path('.' // to_text(int(unit, i4)))
    end function unit_file_path

    !> Writes `lines` to unit `unit`.
    !>  where : out, the file written ('' for the .resu)
    !>  st : STATUS_IO_ERROR naming the file when it cannot be written
    subroutine write_unit_text(ctx, unit, lines, where, st)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: unit
        type(string_t), intent(in) :: lines(:)
        character(len=:), allocatable, intent(out) :: where
        type(status_t), intent(out) :: st
        type(atomic_file_t) :: file
        type(string_t), allocatable :: earlier(:)
        integer :: k
        where = unit_file_path(ctx, unit)
        if (len(where) == 0) then
            do k = 1, size(lines)
                call ctx%write_resu(lines(k)%s)
            end do
            return
        end if
        if (ctx%checking) return
        allocate (earlier(0))
        if (written_before(ctx, where)) call read_lines(where, earlier, st)
        if (st%failed()) return
        call open_atomic(file, where, st)
        if (st%failed()) return
        do k = 1, size(earlier)
            call file%write_line(earlier(k)%s)
        end do
        do k = 1, size(lines)
            call file%write_line(lines(k)%s)
        end do
        call file%commit(st)
        if (st%failed()) return
        call note_written(ctx, where)
    end subroutine write_unit_text

    logical function written_before(ctx, path)
        type(run_context_t), intent(in) :: ctx
        character(len=*), intent(in) :: path
        integer :: k
        written_before = .false.
        if (.not. allocated(ctx%result_files)) return
        do k = 1, size(ctx%result_files)
            if (ctx%result_files(k)%s == path) written_before = .true.
        end do
    end function written_before

    subroutine note_written(ctx, path)
        type(run_context_t), intent(inout) :: ctx
        character(len=*), intent(in) :: path
        type(string_t), allocatable :: bigger(:)
        integer :: n, k
        if (written_before(ctx, path)) return
        n = 0
        if (allocated(ctx%result_files)) n = size(ctx%result_files)
        allocate (bigger(n + 1))
        do k = 1, n
            bigger(k)%s = ctx%result_files(k)%s
        end do
        bigger(n + 1)%s = path
        call move_alloc(bigger, ctx%result_files)
    end subroutine note_written

    !> The lines of a text file this run wrote.
    subroutine read_lines(path, lines, st)
        character(len=*), intent(in) :: path
        type(string_t), allocatable, intent(inout) :: lines(:)
        type(status_t), intent(inout) :: st
        type(string_t), allocatable :: bigger(:)
        character(len=CHUNK) :: buf
        character(len=:), allocatable :: line
        integer :: unit, ios, got, n, k
        open (newunit=unit, file=path, status='old', action='read', form='formatted', &
              iostat=ios)
        if (ios /= 0) then
            call set_error(st, STATUS_IO_ERROR, 'cannot read back ' // path // &
                ', written earlier in this run, to add to it')
            return
        end if
        n = 0
        if (allocated(lines)) deallocate (lines)
        allocate (lines(64))
        do
            line = ''
            do
                read (unit, '(a)', advance='no', size=got, iostat=ios) buf
                line = line // buf(1:got)
                if (ios /= 0) exit
            end do
            if (is_iostat_end(ios)) exit
            if (.not. is_iostat_eor(ios)) then
                call set_error(st, STATUS_IO_ERROR, 'cannot read back ' // path)
                exit
            end if
            if (n == size(lines)) then
                allocate (bigger(2 * n))
                do k = 1, n
                    call move_alloc(lines(k)%s, bigger(k)%s)
                end do
                call move_alloc(bigger, lines)
            end if
            n = n + 1
            lines(n)%s = line
        end do
        close (unit)
        lines = lines(1:n)
    end subroutine read_lines

end module unit_text_output
