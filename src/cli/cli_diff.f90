!> parasol-diff RESULT REFERENCE [--rtol R] [--atol A] [--update] (listings.md, design.md):
!> compares a listing with its reference; text must match, numbers within tolerance.
!> Exit status: 0 same (or reference updated), 1 different, or a usage or I/O error.
module cli_diff
    use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
    use kinds, only: dp
    use status, only: status_t
    use strings, only: string_t, real_short, starts_with
    use cli_args, only: get_arguments
    use atomic_file, only: atomic_file_t, open_atomic
    use listing_diff, only: read_text_lines, compare_listings, parse_number_token, &
                            DIFF_DEFAULT_RTOL, DIFF_DEFAULT_ATOL
    implicit none
    private
    public :: run_parasol_diff

    integer, parameter :: EXIT_SAME = 0, EXIT_DIFFERENT = 1

    !> What the command line asks for.
    type :: diff_request_t
        character(len=:), allocatable :: result_path, reference_path
        real(dp) :: rtol = DIFF_DEFAULT_RTOL
        real(dp) :: atol = DIFF_DEFAULT_ATOL
        logical :: update = .false.
        logical :: help = .false.
    end type diff_request_t

contains

    !> Compares two listings as the command line asks; returns 0 same, 1 different or error.
    subroutine run_parasol_diff(exit_status)
        integer, intent(out) :: exit_status
        type(string_t), allocatable :: args(:)
        type(diff_request_t) :: request
        character(len=:), allocatable :: problem
        call get_arguments(args)
        exit_status = EXIT_DIFFERENT
        call parse_diff_arguments(args, request, problem)
        if (len(problem) > 0) then
            write (error_unit, '(a)') 'parasol-diff: error: ' // problem
            write (error_unit, '(a)') 'usage: parasol-diff RESULT REFERENCE [--rtol R] ' // &
                '[--atol A] [--update] (parasol-diff --help for more)'
            return
        end if
        if (request%help) then
            call print_diff_usage(output_unit)
            exit_status = EXIT_SAME
            return
        end if
        call diff_files(request, exit_status)
    end subroutine run_parasol_diff

    !> Reads both files, prints the differences and the summary, updates when asked.
    subroutine diff_files(request, exit_status)
        type(diff_request_t), intent(in) :: request
        integer, intent(out) :: exit_status
        type(string_t), allocatable :: result_lines(:), reference_lines(:), messages(:)
        type(status_t) :: st
        integer :: n_diff, n_lines, i
        logical :: reference_exists
        character(len=12) :: a, b
        exit_status = EXIT_DIFFERENT
        call read_text_lines(request%result_path, result_lines, st)
        if (st%failed()) then
            write (error_unit, '(a)') 'parasol-diff: error: ' // st%message
            return
        end if
        inquire (file=request%reference_path, exist=reference_exists)
        if (request%update .and. .not. reference_exists) then
            allocate (reference_lines(0))     ! --update may create a first reference
        else
            call read_text_lines(request%reference_path, reference_lines, st)
            if (st%failed()) then
                write (error_unit, '(a)') 'parasol-diff: error: ' // st%message
                return
            end if
        end if
        call compare_listings(result_lines, reference_lines, request%rtol, request%atol, &
                              messages, n_diff, n_lines)
        do i = 1, size(messages)
            write (output_unit, '(a)') messages(i)%s
        end do
        if (n_diff == 0) then
            write (output_unit, '(a)') 'parasol-diff: identical within rtol=' // &
                real_short(request%rtol) // ' atol=' // real_short(request%atol)
            exit_status = EXIT_SAME
            return
        end if
        write (a, '(i0)') n_diff
        write (b, '(i0)') n_lines
        write (output_unit, '(a)') 'parasol-diff: ' // trim(a) // ' differences in ' // &
            trim(b) // ' lines'
        if (request%update) call update_reference(request, result_lines, exit_status)
    end subroutine diff_files

    !> Replaces the reference by the result, atomically (temporary file + rename).
    subroutine update_reference(request, result_lines, exit_status)
        type(diff_request_t), intent(in) :: request
        type(string_t), intent(in) :: result_lines(:)
        integer, intent(inout) :: exit_status
        type(atomic_file_t) :: file
        type(status_t) :: st
        integer :: i
        call open_atomic(file, request%reference_path, st)
        if (st%failed()) then
            write (error_unit, '(a)') 'parasol-diff: error: ' // st%message
            return
        end if
        do i = 1, size(result_lines)
            call file%write_line(result_lines(i)%s)
        end do
        call file%commit(st)
        if (st%failed()) then
            call file%discard()
            write (error_unit, '(a)') 'parasol-diff: error: ' // st%message
            return
        end if
        write (output_unit, '(a)') 'parasol-diff: updated ' // request%reference_path // &
            ' from ' // request%result_path // ' (review the change like code)'
        exit_status = EXIT_SAME
    end subroutine update_reference

    !> Reads the command line into `request`; `problem` is empty, or says what is wrong.
    subroutine parse_diff_arguments(args, request, problem)
        type(string_t), intent(in) :: args(:)
        type(diff_request_t), intent(out) :: request
        character(len=:), allocatable, intent(out) :: problem
        integer :: i, n_paths
        character(len=:), allocatable :: option, value
        problem = ''
        n_paths = 0
        i = 0
        do while (i < size(args))
            i = i + 1
            option = args(i)%s
            if (option == '--help' .or. option == '-h') then
                request%help = .true.
                return
            else if (option == '--update') then
                request%update = .true.
            else if (option == '--rtol' .or. option == '--atol' .or. &
                     starts_with(option, '--rtol=') .or. starts_with(option, '--atol=')) then
                if (index(option, '=') > 0) then
                    value = option(index(option, '=') + 1:)
                    option = option(1:index(option, '=') - 1)
                else if (i < size(args)) then
                    i = i + 1
                    value = args(i)%s
                else
                    problem = option // ' needs a value (e.g. ' // option // ' 1e-9)'
                    return
                end if
                call set_tolerance(request, option, value, problem)
                if (len(problem) > 0) return
            else if (starts_with(option, '-') .and. len(option) > 1) then
                problem = 'unknown option "' // option // '"'
                return
            else
                n_paths = n_paths + 1
                if (n_paths == 1) request%result_path = option
                if (n_paths == 2) request%reference_path = option
            end if
        end do
        if (n_paths /= 2) problem = 'expected two files, RESULT and REFERENCE'
    end subroutine parse_diff_arguments

    !> Sets --rtol or --atol from its text: a non-negative number.
    subroutine set_tolerance(request, option, text, problem)
        type(diff_request_t), intent(inout) :: request
        character(len=*), intent(in) :: option, text
        character(len=:), allocatable, intent(inout) :: problem
        logical :: is_number, is_percent
        real(dp) :: value
        call parse_number_token(text, is_number, value, is_percent)
        if (.not. is_number .or. is_percent .or. value < 0.0_dp) then
            problem = option // ' needs a non-negative number, got "' // text // '"'
            return
        end if
        if (option == '--rtol') then
            request%rtol = value
        else
            request%atol = value
        end if
    end subroutine set_tolerance

    !> Writes the usage text.
    subroutine print_diff_usage(unit)
        integer, intent(in) :: unit
        write (unit, '(a)') &
            'usage: parasol-diff RESULT REFERENCE [--rtol R] [--atol A] [--update]', &
            '  compares two listings line by line: words must be equal, numbers must satisfy', &
            '  |a - b| <= atol + rtol*max(|a|,|b|); prints "LINE: expected ... got ..." for', &
            '  each difference (LINE in RESULT) and a summary.', &
            '  --rtol R   relative tolerance (default 1e-9)', &
            '  --atol A   absolute tolerance (default 1e-15)', &
            '  --update   after printing the differences, replace REFERENCE by RESULT', &
            '             (atomically); a deliberate act, review the change like code', &
            'exit status: 0 same (or reference updated), 1 different or error'
    end subroutine print_diff_usage

end module cli_diff
