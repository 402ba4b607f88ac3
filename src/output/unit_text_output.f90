!> Text written to a logical unit by IMPR_TABLE and IMPR_FONCTION, as Code_Aster writes to
!> its units: unit 8 is the result listing (the `.resu`); another unit goes to its file
!> (unit_files: the bound one, else `<stem>.<N>` in the output folder). A unit
!> written earlier in the run is added to, as Code_Aster appends to an open unit; the file
!> is rewritten atomically each time (atomic_file), so a failed run never leaves half a
!> table.
module unit_text_output
    use kinds, only: i4
    use strings, only: string_t, to_text
    use status, only: status_t
    use atomic_file, only: atomic_file_t, open_atomic
    use run_context, only: run_context_t
    use text_file, only: read_text_file, split_text_lines
    use unit_files, only: unit_file_path, unit_written_in_run
    use deck_command, only: keyword_set_t
    use table_keywords, only: relocate_at
    implicit none
    private

    public :: write_unit_text

contains

    !> Writes `lines` to unit `unit`.
    !>  where : out, the file written ('the .resu' for unit 8)
    !>  st    : STATUS_IO_ERROR naming the file when it cannot be written, located at `key`
    !>          of `scope` when given (the UNITE keyword that named the unit)
    subroutine write_unit_text(ctx, unit, lines, where, st, scope, key)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: unit
        type(string_t), intent(in) :: lines(:)
        character(len=:), allocatable, intent(out) :: where
        type(status_t), intent(out) :: st
        class(keyword_set_t), intent(in), optional :: scope
        character(len=*), intent(in), optional :: key
        call write_lines(ctx, unit, lines, where, st)
        if (st%failed() .and. present(scope) .and. present(key)) &
            call relocate_at(scope, key, st)
        if (len(where) == 0) where = 'the .resu'
    end subroutine write_unit_text

    !> write_unit_text without the location; `where` is '' for the .resu.
    subroutine write_lines(ctx, unit, lines, where, st)
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
        if (unit_written_in_run(ctx, where)) call read_lines(where, earlier, st)
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
    end subroutine write_lines

    subroutine note_written(ctx, path)
        type(run_context_t), intent(inout) :: ctx
        character(len=*), intent(in) :: path
        type(string_t), allocatable :: bigger(:)
        integer :: n, k
        if (unit_written_in_run(ctx, path)) return
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
        character(len=:), allocatable :: text
        call read_text_file(path, 'the file written earlier in this run,', text, st)
        if (st%failed()) return
        call split_text_lines(text, lines)
    end subroutine read_lines

end module unit_text_output
