!> Regular expressions for text filters (CALC_TABLE FILTRE CRIT_COMP='REGEXP', which
!> Code_Aster runs with Python's re.search): the common subset of Python's syntax,
!> compiled to a program of a Pike virtual machine and run by simulating every thread at
!> once, so a search costs O(pattern × text) whatever the pattern (no backtracking, no
!> exponential case on hostile input).
!>
!> Syntax: literal characters; `.` (any character but a new line); classes `[abc]`,
!> `[a-z0-9_]`, `[^...]`; escapes `\d \D \w \W \s \S` (ASCII, as re.ASCII) and `\` before
!> any punctuation; anchors `^` and `$`; groups `( )` (and `(?: )`), alternation `|`;
!> quantifiers `*`, `+`, `?`, `{m}`, `{m,}`, `{m,n}` (a trailing `?`, lazy, is accepted:
!> it does not change whether a text matches). Anything else (back-references,
!> look-arounds, named groups, flags) is refused with the column where it stands.
module text_pattern
    use kinds, only: i4, i8
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use strings, only: to_text
    implicit none
    private

    !> Limits: characters of a pattern, instructions of its program, repetition count.
    integer, parameter, public :: PATTERN_MAX_LENGTH = 1000
    integer, parameter :: MAX_PROGRAM = 20000
    integer, parameter :: MAX_REPEAT = 1000

    !> Instructions (jumps are relative: target = pc + offset).
    integer, parameter :: OP_CHAR = 1, OP_ANY = 2, OP_CLASS = 3, OP_SPLIT = 4, OP_JUMP = 5, &
        OP_MATCH = 6, OP_BEGIN = 7, OP_END = 8

    !> A compiled pattern.
    type, public :: pattern_t
        integer, allocatable :: op(:), a(:), b(:)     !< instruction, operands
        logical, allocatable :: classes(:, :)         !< (0:255, n) character sets
        integer :: n_classes = 0
    end type pattern_t

    !> A relocatable piece of program under construction.
    type :: fragment_t
        integer, allocatable :: op(:), a(:), b(:)
    end type fragment_t

    !> Parser state.
    type :: parser_t
        character(len=:), allocatable :: text
        integer :: pos = 1
        type(pattern_t) :: pattern                  !< receives the classes
    end type parser_t

    public :: compile_pattern, pattern_search

contains

    !> Compiles `text`.
    !>  st : STATUS_MODEL_ERROR naming the column of what is not understood
    subroutine compile_pattern(text, pattern, st)
        character(len=*), intent(in) :: text
        type(pattern_t), intent(out) :: pattern
        type(status_t), intent(inout) :: st
        type(parser_t) :: p
        type(fragment_t) :: body
        if (len(text) > PATTERN_MAX_LENGTH) then
            call set_error(st, STATUS_MODEL_ERROR, 'the regular expression is longer than ' // &
                to_text(int(PATTERN_MAX_LENGTH, i4)) // ' characters')
            return
        end if
        p%text = text
        allocate (p%pattern%classes(0:255, 0))
        call parse_alternation(p, body, st)
        if (st%failed()) return
        if (p%pos <= len(text)) then
            call fail(p, 'unbalanced '')''', st)
            return
        end if
        call append(body, OP_MATCH, 0, 0)
        if (size(body%op) > MAX_PROGRAM) then
            call set_error(st, STATUS_MODEL_ERROR, 'the regular expression ''' // text // &
                ''' is too large once its repetitions are expanded')
            return
        end if
        pattern = p%pattern
        pattern%op = body%op
        pattern%a = body%a
        pattern%b = body%b
    end subroutine compile_pattern

    !> True when `text` contains a match of `pattern` (Python's re.search).
    logical function pattern_search(pattern, text) result(found)
        type(pattern_t), intent(in) :: pattern
        character(len=*), intent(in) :: text
        logical, allocatable :: current(:), next(:), seen(:)
        integer :: n, i, pc, c
        n = size(pattern%op)
        allocate (current(n), next(n), seen(n))
        current = .false.
        found = .false.
        do i = 1, len(text) + 1
            ! a new thread starts at every position (an unanchored search)
            seen = .false.
            call add_thread(1, i)
            if (found) return
            if (i > len(text)) exit
            c = iachar(text(i:i))
            next = .false.
            do pc = 1, n
                if (.not. current(pc)) cycle
                select case (pattern%op(pc))
                case (OP_CHAR)
                    if (c == pattern%a(pc)) next(pc + 1) = .true.
                case (OP_ANY)
                    if (c /= 10) next(pc + 1) = .true.
                case (OP_CLASS)
                    if (pattern%classes(c, pattern%a(pc))) next(pc + 1) = .true.
                end select
            end do
            ! follow the jumps of the threads that moved, at position i + 1
            current = .false.
            seen = .false.
            do pc = 1, n
                if (next(pc)) call add_thread(pc, i + 1)
                if (found) return
            end do
        end do
    contains
        !> Adds thread `pc` at text position `at`, following jumps, splits and anchors.
        recursive subroutine add_thread(pc, at)
            integer, intent(in) :: pc, at
            if (pc < 1 .or. pc > n) return
            if (seen(pc)) return
            seen(pc) = .true.
            select case (pattern%op(pc))
            case (OP_JUMP)
                call add_thread(pc + pattern%a(pc), at)
            case (OP_SPLIT)
                call add_thread(pc + pattern%a(pc), at)
                call add_thread(pc + pattern%b(pc), at)
            case (OP_BEGIN)
                if (at == 1) call add_thread(pc + 1, at)
            case (OP_END)
                if (at == len(text) + 1) call add_thread(pc + 1, at)
                if (at == len(text)) then     ! Python's $ also matches before a final \n
                    if (text(at:at) == new_line('a')) call add_thread(pc + 1, at)
                end if
            case (OP_MATCH)
                found = .true.
            case default
                current(pc) = .true.
            end select
        end subroutine add_thread
    end function pattern_search

    ! ---- parser: alternation > concatenation > repetition > atom ----------------------

    recursive subroutine parse_alternation(p, out, st)
        type(parser_t), intent(inout) :: p
        type(fragment_t), intent(out) :: out
        type(status_t), intent(inout) :: st
        type(fragment_t) :: right, joined
        call parse_concatenation(p, out, st)
        if (st%failed()) return
        do while (peek(p) == '|')
            p%pos = p%pos + 1
            call parse_concatenation(p, right, st)
            if (st%failed()) return
            ! SPLIT +1, +len(out)+2; out; JUMP +len(right)+1; right
            call empty(joined)
            call append(joined, OP_SPLIT, 1, size(out%op) + 2)
            call extend(joined, out)
            call append(joined, OP_JUMP, size(right%op) + 1, 0)
            call extend(joined, right)
            out = joined
        end do
    end subroutine parse_alternation

    recursive subroutine parse_concatenation(p, out, st)
        type(parser_t), intent(inout) :: p
        type(fragment_t), intent(out) :: out
        type(status_t), intent(inout) :: st
        type(fragment_t) :: piece
        call empty(out)
        do while (p%pos <= len(p%text))
            if (peek(p) == '|' .or. peek(p) == ')') exit
            call parse_repetition(p, piece, st)
            if (st%failed()) return
            call extend(out, piece)
            if (size(out%op) > MAX_PROGRAM) then
                call fail(p, 'the expression is too large', st)
                return
            end if
        end do
    end subroutine parse_concatenation

    recursive subroutine parse_repetition(p, out, st)
        type(parser_t), intent(inout) :: p
        type(fragment_t), intent(out) :: out
        type(status_t), intent(inout) :: st
        type(fragment_t) :: atom
        integer :: low, high, start
        character :: q
        start = p%pos
        call parse_atom(p, atom, st)
        if (st%failed()) return
        out = atom
        do while (p%pos <= len(p%text))
            q = peek(p)
            select case (q)
            case ('*')
                low = 0; high = -1
                p%pos = p%pos + 1
            case ('+')
                low = 1; high = -1
                p%pos = p%pos + 1
            case ('?')
                low = 0; high = 1
                p%pos = p%pos + 1
            case ('{')
                if (.not. read_braces(p, low, high, st)) exit   ! a literal '{'
                if (st%failed()) return
            case default
                exit
            end select
            if (atom_is_anchor(atom)) then
                call fail(p, 'nothing to repeat', st)
                return
            end if
            if (peek(p) == '?') p%pos = p%pos + 1       ! lazy: same language
            call repeat_fragment(atom, low, high, out, st)
            if (st%failed()) return
            atom = out
        end do
        if (size(out%op) > MAX_PROGRAM) then
            p%pos = start
            call fail(p, 'the repetition is too large', st)
        end if
    end subroutine parse_repetition

    !> `e{low,high}` (high < 0: unbounded) as copies of e.
    subroutine repeat_fragment(e, low, high, out, st)
        type(fragment_t), intent(in) :: e
        integer, intent(in) :: low, high
        type(fragment_t), intent(out) :: out
        type(status_t), intent(inout) :: st
        type(fragment_t) :: optional
        integer :: k, n
        call empty(out)
        n = size(e%op)
        if (int(n, i8) * max(low, high, 1) > MAX_PROGRAM) then
            call set_error(st, STATUS_MODEL_ERROR, 'the regular expression is too large ' // &
                'once its repetitions are expanded')
            return
        end if
        do k = 1, low
            call extend(out, e)
        end do
        if (high < 0) then
            ! SPLIT +1, +n+2; e; JUMP -(n+1)
            call append(out, OP_SPLIT, 1, n + 2)
            call extend(out, e)
            call append(out, OP_JUMP, -(n + 1), 0)
        else
            do k = low + 1, high
                call empty(optional)
                call append(optional, OP_SPLIT, 1, n + 1)
                call extend(optional, e)
                call extend(out, optional)
            end do
        end if
    end subroutine repeat_fragment

    !> Reads `{m}`, `{m,}`, `{m,n}` after the atom; false (position unchanged) when the
    !> brace does not start a count (Python then takes it literally).
    logical function read_braces(p, low, high, st) result(is_count)
        type(parser_t), intent(inout) :: p
        integer, intent(out) :: low, high
        type(status_t), intent(inout) :: st
        integer :: close, comma, ios
        character(len=:), allocatable :: inside
        is_count = .false.
        low = 0; high = 0
        close = index(p%text(p%pos:), '}')
        if (close == 0) return
        inside = p%text(p%pos + 1:p%pos + close - 2)
        if (len(inside) == 0 .or. verify(inside, '0123456789,') /= 0) return
        comma = index(inside, ',')
        if (comma == 1) return
        if (comma == 0) then
            read (inside, *, iostat=ios) low
            high = low
        else
            read (inside(1:comma - 1), *, iostat=ios) low
            if (ios == 0) then
                if (comma == len(inside)) then
                    high = -1
                else
                    read (inside(comma + 1:), *, iostat=ios) high
                end if
            end if
        end if
        if (ios /= 0 .or. low > MAX_REPEAT .or. high > MAX_REPEAT .or. &
            (high >= 0 .and. high < low)) then
            call fail(p, 'bad repetition count {' // inside // '} (at most ' // &
                to_text(int(MAX_REPEAT, i4)) // ', minimum first)', st)
            is_count = .true.
            return
        end if
        p%pos = p%pos + close
        is_count = .true.
    end function read_braces

    recursive subroutine parse_atom(p, out, st)
        type(parser_t), intent(inout) :: p
        type(fragment_t), intent(out) :: out
        type(status_t), intent(inout) :: st
        character :: c
        call empty(out)
        c = peek(p)
        select case (c)
        case ('(')
            p%pos = p%pos + 1
            if (peek(p) == '?') then
                if (p%pos + 1 <= len(p%text)) then
                    if (p%text(p%pos + 1:p%pos + 1) == ':') then
                        p%pos = p%pos + 2
                    else
                        call fail(p, 'group extensions (?...) other than (?:...) are not ' // &
                            'supported', st)
                        return
                    end if
                end if
            end if
            call parse_alternation(p, out, st)
            if (st%failed()) return
            if (peek(p) /= ')') then
                call fail(p, 'missing '')''', st)
                return
            end if
            p%pos = p%pos + 1
        case ('.')
            call append(out, OP_ANY, 0, 0)
            p%pos = p%pos + 1
        case ('^')
            call append(out, OP_BEGIN, 0, 0)
            p%pos = p%pos + 1
        case ('$')
            call append(out, OP_END, 0, 0)
            p%pos = p%pos + 1
        case ('[')
            call parse_class(p, out, st)
        case ('\')
            call parse_escape(p, out, st)
        case ('*', '+', '?')
            call fail(p, 'nothing to repeat', st)
        case default
            call append(out, OP_CHAR, iachar(c), 0)
            p%pos = p%pos + 1
        end select
    end subroutine parse_atom

    !> `\d`, `\w`, `\s` and their negations, or an escaped punctuation character.
    subroutine parse_escape(p, out, st)
        type(parser_t), intent(inout) :: p
        type(fragment_t), intent(inout) :: out
        type(status_t), intent(inout) :: st
        logical :: set(0:255)
        character :: c
        if (p%pos >= len(p%text)) then
            call fail(p, 'a pattern cannot end with \', st)
            return
        end if
        c = p%text(p%pos + 1:p%pos + 1)
        if (index('dDwWsS', c) > 0) then
            call escape_set(c, set)
            call append(out, OP_CLASS, add_class(p, set), 0)
        else if (is_punctuation(c)) then
            call append(out, OP_CHAR, iachar(c), 0)
        else if (c == 'n' .or. c == 't') then
            call append(out, OP_CHAR, merge(10, 9, c == 'n'), 0)
        else
            call fail(p, 'the escape \' // c // ' is not supported (\d \w \s, their ' // &
                'capitals, \n, \t and \ before punctuation are)', st)
            return
        end if
        p%pos = p%pos + 2
    end subroutine parse_escape

    !> `[...]`: ranges, escapes, a leading ^ for the complement.
    subroutine parse_class(p, out, st)
        type(parser_t), intent(inout) :: p
        type(fragment_t), intent(inout) :: out
        type(status_t), intent(inout) :: st
        logical :: set(0:255), sub(0:255), negate
        integer :: first, last, start
        character :: c
        start = p%pos
        p%pos = p%pos + 1
        set = .false.
        negate = peek(p) == '^'
        if (negate) p%pos = p%pos + 1
        first = -1
        do
            if (p%pos > len(p%text)) then
                p%pos = start
                call fail(p, 'missing '']''', st)
                return
            end if
            c = p%text(p%pos:p%pos)
            if (c == ']' .and. first /= -2) then
                if (p%pos > start + 1 + merge(1, 0, negate)) exit
            end if
            if (c == '\' .and. p%pos < len(p%text)) then
                c = p%text(p%pos + 1:p%pos + 1)
                p%pos = p%pos + 2
                if (index('dDwWsS', c) > 0) then
                    call escape_set(c, sub)
                    set = set .or. sub
                    cycle
                end if
                if (c == 'n') c = achar(10)
                if (c == 't') c = achar(9)
            else
                p%pos = p%pos + 1
            end if
            first = iachar(c)
            last = first
            if (p%pos + 1 <= len(p%text)) then
                if (p%text(p%pos:p%pos) == '-' .and. p%text(p%pos + 1:p%pos + 1) /= ']') then
                    last = iachar(p%text(p%pos + 1:p%pos + 1))
                    p%pos = p%pos + 2
                    if (last < first) then
                        call fail(p, 'bad character range', st)
                        return
                    end if
                end if
            end if
            set(first:last) = .true.
        end do
        p%pos = p%pos + 1
        if (negate) set = .not. set
        call append(out, OP_CLASS, add_class(p, set), 0)
    end subroutine parse_class

    subroutine escape_set(c, set)
        character, intent(in) :: c
        logical, intent(out) :: set(0:255)
        set = .false.
        select case (c)
        case ('d', 'D')
            set(iachar('0'):iachar('9')) = .true.
        case ('w', 'W')
            set(iachar('0'):iachar('9')) = .true.
            set(iachar('a'):iachar('z')) = .true.
            set(iachar('A'):iachar('Z')) = .true.
            set(iachar('_')) = .true.
        case default
            set([9, 10, 11, 12, 13, 32]) = .true.
        end select
        if (c == 'D' .or. c == 'W' .or. c == 'S') set = .not. set
    end subroutine escape_set

    integer function add_class(p, set) result(k)
        type(parser_t), intent(inout) :: p
        logical, intent(in) :: set(0:255)
        logical, allocatable :: bigger(:, :)
        k = p%pattern%n_classes + 1
        allocate (bigger(0:255, k))
        if (k > 1) bigger(:, 1:k - 1) = p%pattern%classes(:, 1:k - 1)
        bigger(:, k) = set
        call move_alloc(bigger, p%pattern%classes)
        p%pattern%n_classes = k
    end function add_class

    pure logical function is_punctuation(c)
        character, intent(in) :: c
        is_punctuation = index('.^$*+?{}[]\|()-/ #&~,:;=<>!"''%@`', c) > 0
    end function is_punctuation

    pure logical function atom_is_anchor(f)
        type(fragment_t), intent(in) :: f
        atom_is_anchor = .false.
        if (size(f%op) == 1) atom_is_anchor = f%op(1) == OP_BEGIN .or. f%op(1) == OP_END
    end function atom_is_anchor

    character function peek(p)
        type(parser_t), intent(in) :: p
        peek = achar(0)
        if (p%pos <= len(p%text)) peek = p%text(p%pos:p%pos)
    end function peek

    subroutine fail(p, message, st)
        type(parser_t), intent(in) :: p
        character(len=*), intent(in) :: message
        type(status_t), intent(inout) :: st
        call set_error(st, STATUS_MODEL_ERROR, 'regular expression ''' // p%text // &
            ''', column ' // to_text(int(p%pos, i4)) // ': ' // message)
    end subroutine fail

    ! ---- fragments -------------------------------------------------------------------

    subroutine empty(f)
        type(fragment_t), intent(out) :: f
        allocate (f%op(0), f%a(0), f%b(0))
    end subroutine empty

    subroutine append(f, op, a, b)
        type(fragment_t), intent(inout) :: f
        integer, intent(in) :: op, a, b
        if (.not. allocated(f%op)) call empty(f)
        f%op = [f%op, op]
        f%a = [f%a, a]
        f%b = [f%b, b]
    end subroutine append

    subroutine extend(f, g)
        type(fragment_t), intent(inout) :: f
        type(fragment_t), intent(in) :: g
        if (.not. allocated(f%op)) call empty(f)
        f%op = [f%op, g%op]
        f%a = [f%a, g%a]
        f%b = [f%b, g%b]
    end subroutine extend

end module text_pattern
