!> Lexer of the deck language (doc/deck-language.md, "Lexical rules"): turns deck text into
!> tokens that carry their line and column. Python's rules, restricted to the subset: `#`
!> comments, `;` and newlines end statements, newlines inside ( ) and [ ] are ignored,
!> indentation gives INDENT/DEDENT tokens (for `def` and `if` blocks), all string forms.
!> Bytes are checked first: NUL bytes and invalid UTF-8 are refused with their location.
module deck_lexer
    use kinds, only: i4
    use status, only: status_t, set_error, STATUS_DECK_ERROR
    use strings, only: to_text
    implicit none
    private

    integer, parameter, public :: TOK_EOF = 0, TOK_NAME = 1, TOK_INT = 2, TOK_REAL = 3, &
        TOK_STRING = 4, TOK_OP = 5, TOK_NEWLINE = 6, TOK_INDENT = 7, TOK_DEDENT = 8

    !> Deepest bracket nesting accepted by the lexer (the parser has its own depth limit).
    integer, parameter :: MAX_BRACKETS = 200
    integer, parameter :: MAX_INDENT_LEVELS = 100

    !> One token. `text` is the source spelling, or the decoded value of a string literal.
    type, public :: token_t
        integer(i4) :: kind = TOK_EOF
        character(len=:), allocatable :: text
        integer(i4) :: line = 0
        integer(i4) :: col = 0
    end type token_t

    public :: tokenize, check_bytes

contains

    !> Checks that `text` holds no NUL byte and is valid UTF-8.
    !>  text : in, the file contents;  file : in, its name for messages
    !>  st   : out, STATUS_DECK_ERROR at the first bad byte
    subroutine check_bytes(text, file, st)
        character(len=*), intent(in) :: text, file
        type(status_t), intent(out) :: st
        integer :: i, c, need, line, col, k
        i = 1; line = 1; col = 1
        do while (i <= len(text))
            c = iachar(text(i:i))
            if (c == 0) then
                call set_error(st, STATUS_DECK_ERROR, 'NUL byte in the deck: this is not a ' // &
                    'text file (a deck is UTF-8 or ASCII text)', file=file, line=line, column=col)
                return
            end if
            need = 0
            if (c >= 128) then
                if (c >= 194 .and. c <= 223) then
                    need = 1
                else if (c >= 224 .and. c <= 239) then
                    need = 2
                else if (c >= 240 .and. c <= 244) then
                    need = 3
                else
                    need = -1
                end if
                if (need > 0 .and. i + need > len(text)) need = -1
                if (need > 0) then
                    do k = 1, need
                        if (iand(iachar(text(i + k:i + k)), 192) /= 128) need = -1
                        if (need < 0) exit
                    end do
                end if
                if (need < 0) then
                    call set_error(st, STATUS_DECK_ERROR, 'invalid UTF-8 byte in the deck ' // &
                        '(save the file as UTF-8 text)', file=file, line=line, column=col)
                    return
                end if
            end if
            if (c == 10) then
                line = line + 1; col = 1
            else
                col = col + 1
            end if
            i = i + 1 + need
        end do
    end subroutine check_bytes

    !> Splits `text` into tokens.
    !>  text   : in, deck text (any of LF, CRLF line ends; tabs count as indentation)
    !>  file   : in, file name used in messages
    !>  tokens : out, the tokens, ending with NEWLINE, DEDENTs and EOF
    !>  st     : out, STATUS_DECK_ERROR with the location of a bad character, unterminated
    !>           string or bracket, bad indentation
    !>  line0, col0 : in, optional position of text(1:1) (for expressions inside a string)
    subroutine tokenize(text, file, tokens, st, line0, col0)
        character(len=*), intent(in) :: text, file
        type(token_t), allocatable, intent(out) :: tokens(:)
        type(status_t), intent(out) :: st
        integer, intent(in), optional :: line0, col0
        integer :: i, n, line, col, depth, ntok, nind, indents(MAX_INDENT_LEVELS)
        integer :: open_line(MAX_BRACKETS), open_col(MAX_BRACKETS)
        logical :: at_line_start
        character :: ch
        allocate (tokens(64))
        ntok = 0; n = len(text); i = 1
        line = 1; col = 1
        if (present(line0)) line = line0
        if (present(col0)) col = col0
        depth = 0; nind = 1; indents(1) = 0; at_line_start = .true.
        do while (i <= n)
            if (at_line_start .and. depth == 0) then
                call handle_indent()
                if (st%failed()) return
                if (i > n) exit
            end if
            ch = text(i:i)
            select case (ch)
            case (' ', achar(9), achar(12), achar(13))
                i = i + 1; col = col + 1
            case ('#')
                do while (i <= n)
                    if (text(i:i) == achar(10)) exit
                    i = i + 1
                end do
            case (achar(10))
                if (depth == 0) call newline_token(line, col)
                i = i + 1; line = line + 1; col = 1
                at_line_start = .true.
            case ('\')
                if (i < n .and. text(min(i + 1, n):min(i + 1, n)) == achar(10)) then
                    i = i + 2; line = line + 1; col = 1
                else if (i + 1 < n .and. &
                         text(min(i + 1, n):min(i + 2, n)) == achar(13) // achar(10)) then
                    i = i + 3; line = line + 1; col = 1
                else
                    call fail('unexpected character "\"', line, col); return
                end if
            case ("'", '"')
                call lex_string()
                if (st%failed()) return
            case ('0':'9', '.')
                if (ch == '.' .and. .not. next_is_digit(i + 1)) then
                    call push(TOK_OP, '.', line, col)
                    i = i + 1; col = col + 1
                else
                    call lex_number()
                    if (st%failed()) return
                end if
            case ('a':'z', 'A':'Z', '_')
                call lex_name()
            case ('(', '[', '{')
                if (depth >= MAX_BRACKETS) then
                    call fail('brackets nested deeper than ' // to_text(MAX_BRACKETS) // &
                        ' levels (simplify the expression)', line, col); return
                end if
                depth = depth + 1
                open_line(depth) = line; open_col(depth) = col
                call push(TOK_OP, ch, line, col)
                i = i + 1; col = col + 1
            case (')', ']', '}')
                if (depth == 0) then
                    call fail('unmatched "' // ch // '"', line, col); return
                end if
                depth = depth - 1
                call push(TOK_OP, ch, line, col)
                i = i + 1; col = col + 1
            case default
                call lex_operator()
                if (st%failed()) return
            end select
        end do
        if (depth > 0) then
            call fail('unbalanced bracket: "' // '(' // '" opened here is never closed ' // &
                '(add the missing closing bracket)', open_line(depth), open_col(depth))
            return
        end if
        call newline_token(line, col)
        do while (nind > 1)
            call push(TOK_DEDENT, '', line, col)
            nind = nind - 1
        end do
        call push(TOK_EOF, '', line, col)
        tokens = tokens(1:ntok)

    contains

        subroutine fail(message, l, c)
            character(len=*), intent(in) :: message
            integer, intent(in) :: l, c
            call set_error(st, STATUS_DECK_ERROR, message, file=file, line=l, column=c)
        end subroutine fail

        subroutine push(kind, txt, l, c)
            integer, intent(in) :: kind, l, c
            character(len=*), intent(in) :: txt
            type(token_t), allocatable :: bigger(:)
            if (ntok == size(tokens)) then
                allocate (bigger(2 * size(tokens)))
                bigger(1:ntok) = tokens(1:ntok)
                call move_alloc(bigger, tokens)
            end if
            ntok = ntok + 1
            tokens(ntok)%kind = kind
            tokens(ntok)%text = txt
            tokens(ntok)%line = l
            tokens(ntok)%col = c
        end subroutine push

        !> A NEWLINE token, not repeated and not at the start.
        subroutine newline_token(l, c)
            integer, intent(in) :: l, c
            if (ntok == 0) return
            if (tokens(ntok)%kind == TOK_NEWLINE .or. tokens(ntok)%kind == TOK_INDENT .or. &
                tokens(ntok)%kind == TOK_DEDENT) return
            call push(TOK_NEWLINE, '', l, c)
        end subroutine newline_token

        !> Measures the indentation of a logical line and emits INDENT/DEDENT tokens.
        !> Blank and comment-only lines do not count.
        subroutine handle_indent()
            integer :: width, j, c
            width = 0; j = i; c = col
            do while (j <= n)
                if (text(j:j) == ' ') then
                    width = width + 1
                else if (text(j:j) == achar(9)) then
                    width = (width / 8 + 1) * 8
                else if (text(j:j) /= achar(12)) then
                    exit
                end if
                j = j + 1; c = c + 1
            end do
            i = j; col = c
            at_line_start = .false.
            if (j > n) return
            if (text(j:j) == '#' .or. text(j:j) == achar(10) .or. text(j:j) == achar(13)) then
                at_line_start = .true.
                return
            end if
            if (width > indents(nind)) then
                if (nind == MAX_INDENT_LEVELS) then
                    call fail('blocks nested too deeply', line, col); return
                end if
                nind = nind + 1; indents(nind) = width
                call push(TOK_INDENT, '', line, col)
            else
                do while (width < indents(nind))
                    nind = nind - 1
                    call push(TOK_DEDENT, '', line, col)
                end do
                if (width /= indents(nind)) then
                    call fail('inconsistent indentation (align with an enclosing block)', &
                              line, col)
                end if
            end if
        end subroutine handle_indent

        logical function next_is_digit(j)
            integer, intent(in) :: j
            next_is_digit = .false.
            if (j > n) return
            next_is_digit = index('0123456789', text(j:j)) > 0
        end function next_is_digit

        subroutine lex_name()
            integer :: j
            j = i
            do while (j <= n)
                if (index('abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_', &
                          text(j:j)) == 0) exit
                j = j + 1
            end do
            call push(TOK_NAME, text(i:j - 1), line, col)
            col = col + (j - i); i = j
        end subroutine lex_name

        subroutine lex_number()
            integer :: j, kind
            logical :: is_real
            j = i; is_real = .false.
            do while (j <= n)
                if (index('0123456789', text(j:j)) == 0) exit
                j = j + 1
            end do
            if (j <= n) then
                if (text(j:j) == '.') then
                    is_real = .true.; j = j + 1
                    do while (j <= n)
                        if (index('0123456789', text(j:j)) == 0) exit
                        j = j + 1
                    end do
                end if
            end if
            if (j <= n) then
                if (text(j:j) == 'e' .or. text(j:j) == 'E') then
                    is_real = .true.; j = j + 1
                    if (j <= n) then
                        if (text(j:j) == '+' .or. text(j:j) == '-') j = j + 1
                    end if
                    if (.not. next_is_digit(j)) then
                        call fail('malformed number "' // text(i:j - 1) // &
                            '" (an exponent needs digits, e.g. 1.0E+03)', line, col)
                        return
                    end if
                    do while (j <= n)
                        if (index('0123456789', text(j:j)) == 0) exit
                        j = j + 1
                    end do
                end if
            end if
            if (j <= n) then
                if (index('abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ_', &
                          text(j:j)) > 0) then
                    call fail('malformed number "' // text(i:j) // '"', line, col)
                    return
                end if
            end if
            kind = TOK_INT
            if (is_real) kind = TOK_REAL
            call push(kind, text(i:j - 1), line, col)
            col = col + (j - i); i = j
        end subroutine lex_number

        !> Strings: '...', "...", '''...''', """...""" with \\ \' \" \n \t escapes.
        subroutine lex_string()
            character :: q
            logical :: triple
            character(len=:), allocatable :: buf
            integer :: l0, c0, nb
            q = text(i:i); l0 = line; c0 = col
            triple = .false.
            if (i + 2 <= n) triple = text(i:i + 2) == q // q // q
            if (triple) then
                i = i + 3; col = col + 3
            else
                i = i + 1; col = col + 1
            end if
            allocate (character(len=64) :: buf)
            nb = 0
            do
                if (i > n) then
                    call fail('unterminated string: the quote opened here is never closed', &
                              l0, c0)
                    return
                end if
                if (triple) then
                    if (i + 2 <= n) then
                        if (text(i:i + 2) == q // q // q) then
                            i = i + 3; col = col + 3; exit
                        end if
                    end if
                else if (text(i:i) == q) then
                    i = i + 1; col = col + 1; exit
                else if (text(i:i) == achar(10)) then
                    call fail('unterminated string: a quoted string ends at the end of ' // &
                        'its line (use triple quotes for several lines)', l0, c0)
                    return
                end if
                if (text(i:i) == '\' .and. i < n) then
                    select case (text(i + 1:i + 1))
                    case ('n')
                        call append_text(buf, nb, achar(10))
                    case ('t')
                        call append_text(buf, nb, achar(9))
                    case ("'", '"', '\')
                        call append_text(buf, nb, text(i + 1:i + 1))
                    case (achar(10))
                        line = line + 1; col = -1
                    case default
                        call append_text(buf, nb, text(i:i + 1))
                    end select
                    i = i + 2; col = col + 2
                    cycle
                end if
                if (text(i:i) == achar(10)) then
                    line = line + 1; col = 0
                end if
                if (text(i:i) /= achar(13)) call append_text(buf, nb, text(i:i))
                i = i + 1; col = col + 1
            end do
            call push(TOK_STRING, buf(1:nb), l0, c0)
        end subroutine lex_string

        subroutine lex_operator()
            character(len=2) :: two
            two = '  '
            if (i + 1 <= n) two = text(i:i + 1)
            select case (two)
            case ('**', '//', '<=', '>=', '==', '!=', '->', '+=', '-=', '*=', '/=')
                call push(TOK_OP, two, line, col)
                i = i + 2; col = col + 2
                return
            end select
            select case (text(i:i))
            case ('+', '-', '*', '/', '%', '<', '>', '=', ',', ':', ';', '@', '&', '|', '^', '~')
                call push(TOK_OP, text(i:i), line, col)
                i = i + 1; col = col + 1
            case default
                if (iachar(text(i:i)) >= 128) then
                    call fail('non-ASCII character outside a string or comment ' // &
                              '(names are ASCII)', line, col)
                else
                    call fail('unexpected character "' // text(i:i) // '"', line, col)
                end if
            end select
        end subroutine lex_operator

    end subroutine tokenize

    !> Appends `s` to buf(1:nb), growing buf geometrically.
    pure subroutine append_text(buf, nb, s)
        character(len=:), allocatable, intent(inout) :: buf
        integer, intent(inout) :: nb
        character(len=*), intent(in) :: s
        character(len=:), allocatable :: tmp
        if (nb + len(s) > len(buf)) then
            allocate (character(len=2 * len(buf) + len(s)) :: tmp)
            tmp(1:nb) = buf(1:nb)
            call move_alloc(tmp, buf)
        end if
        buf(nb + 1:nb + len(s)) = s
        nb = nb + len(s)
    end subroutine append_text


end module deck_lexer
