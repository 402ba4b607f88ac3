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
        TOK_STRING = 4, TOK_OP = 5, TOK_NEWLINE = 6, TOK_INDENT = 7, TOK_DEDENT = 8, &
        TOK_FSTRING = 9

    !> Deepest bracket nesting accepted by the lexer (the parser has its own depth limit).
    integer, parameter :: MAX_BRACKETS = 200
    integer, parameter :: MAX_INDENT_LEVELS = 100

    !> One token. `text` is the source spelling, or the decoded value of a string literal;
    !> for an f-string (TOK_FSTRING) the text between its quotes as written (the parser
    !> reads its fields), `skip` the columns from the token's start to that text (prefix and
    !> quotes), `raw` its r prefix (no escapes).
    type, public :: token_t
        integer(i4) :: kind = TOK_EOF
        character(len=:), allocatable :: text
        integer(i4) :: line = 0
        integer(i4) :: col = 0
        integer(i4) :: skip = 0
        logical :: raw = .false.
    end type token_t

    !> State of one tokenize call: the read position (byte i of n, at line/col), the open
    !> brackets (where each was opened, for the unbalanced-bracket message), the indentation
    !> widths of the enclosing blocks, and the tokens made so far, tokens(1:ntok).
    type :: lexer_t
        integer :: n = 0
        integer :: i = 1
        integer :: line = 1
        integer :: col = 1
        integer :: depth = 0
        integer :: open_line(MAX_BRACKETS) = 0
        integer :: open_col(MAX_BRACKETS) = 0
        integer :: nind = 1
        integer :: indents(MAX_INDENT_LEVELS) = 0
        logical :: at_line_start = .true.
        integer :: ntok = 0
        type(token_t), allocatable :: tokens(:)
        character(len=:), allocatable :: file
    end type lexer_t

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

    !> Splits `text` into tokens. The work is done by one procedure per token family
    !> (lex_indentation, lex_token and the lex_* readers it dispatches to, finish_tokens);
    !> they share the read position and the token list through a lexer_t.
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
        type(lexer_t) :: lx
        allocate (lx%tokens(64))
        lx%n = len(text)
        lx%file = file
        if (present(line0)) lx%line = line0
        if (present(col0)) lx%col = col0
        do while (lx%i <= lx%n)
            if (lx%at_line_start .and. lx%depth == 0) then
                call lex_indentation(lx, text, st)
                if (st%failed()) exit
                if (lx%i > lx%n) exit
            end if
            call lex_token(lx, text, st)
            if (st%failed()) exit
        end do
        if (.not. st%failed()) call finish_tokens(lx, st)
        if (.not. st%failed()) lx%tokens = lx%tokens(1:lx%ntok)
        call move_alloc(lx%tokens, tokens)
    end subroutine tokenize

    !> Reads the token (or skips the blank, comment or line continuation) that starts at
    !> text(lx%i), choosing the reader by its first character.
    !>  lx : inout, lexer state, advanced past what was read
    !>  st : out, STATUS_DECK_ERROR from the reader, located
    subroutine lex_token(lx, text, st)
        type(lexer_t), intent(inout) :: lx
        character(len=*), intent(in) :: text
        type(status_t), intent(out) :: st
        character :: ch
        ch = text(lx%i:lx%i)
        select case (ch)
        case (' ', achar(9), achar(12), achar(13))
            lx%i = lx%i + 1; lx%col = lx%col + 1
        case ('#')
            call skip_comment(lx, text)
        case (achar(10))
            call lex_line_end(lx)
        case ('\')
            call skip_line_continuation(lx, text, st)
        case ("'", '"')
            call lex_string(lx, text, st)
        case ('0':'9', '.')
            ! A dot not followed by a digit is the attribute operator (`a.b`), not `.5`.
            if (ch == '.' .and. .not. next_is_digit(text, lx%i + 1)) then
                call push_token(lx, TOK_OP, '.', lx%line, lx%col)
                lx%i = lx%i + 1; lx%col = lx%col + 1
            else
                call lex_number(lx, text, st)
            end if
        case ('a':'z', 'A':'Z', '_')
            if (string_prefix(text, lx%i) > 0) then
                call lex_string(lx, text, st)
            else
                call lex_name(lx, text)
            end if
        case ('(', '[', '{', ')', ']', '}')
            call lex_bracket(lx, ch, st)
        case default
            call lex_operator(lx, text, st)
        end select
    end subroutine lex_token

    !> Ends the token list at the end of the text: refuses a bracket still open (located
    !> where it was opened), then adds the last NEWLINE, a DEDENT per open block and EOF.
    !>  lx : inout, lexer state at the end of the text
    !>  st : out, STATUS_DECK_ERROR for an unbalanced bracket
    subroutine finish_tokens(lx, st)
        type(lexer_t), intent(inout) :: lx
        type(status_t), intent(out) :: st
        if (lx%depth > 0) then
            call lex_fail(lx, st, 'unbalanced bracket: "' // '(' // '" opened here is never ' &
                // 'closed (add the missing closing bracket)', lx%open_line(lx%depth), &
                lx%open_col(lx%depth))
            return
        end if
        call push_newline(lx, lx%line, lx%col)
        do while (lx%nind > 1)
            call push_token(lx, TOK_DEDENT, '', lx%line, lx%col)
            lx%nind = lx%nind - 1
        end do
        call push_token(lx, TOK_EOF, '', lx%line, lx%col)
    end subroutine finish_tokens

    !> Sets a STATUS_DECK_ERROR at line l, column c of the lexer's file.
    subroutine lex_fail(lx, st, message, l, c)
        type(lexer_t), intent(in) :: lx
        type(status_t), intent(out) :: st
        character(len=*), intent(in) :: message
        integer, intent(in) :: l, c
        call set_error(st, STATUS_DECK_ERROR, message, file=lx%file, line=l, column=c)
    end subroutine lex_fail

    !> Appends a token (kind, text, line l, column c), doubling the list when it is full.
    subroutine push_token(lx, kind, txt, l, c)
        type(lexer_t), intent(inout) :: lx
        integer, intent(in) :: kind, l, c
        character(len=*), intent(in) :: txt
        type(token_t), allocatable :: bigger(:)
        if (lx%ntok == size(lx%tokens)) then
            allocate (bigger(2 * size(lx%tokens)))
            bigger(1:lx%ntok) = lx%tokens(1:lx%ntok)
            call move_alloc(bigger, lx%tokens)
        end if
        lx%ntok = lx%ntok + 1
        lx%tokens(lx%ntok)%kind = kind
        lx%tokens(lx%ntok)%text = txt
        lx%tokens(lx%ntok)%line = l
        lx%tokens(lx%ntok)%col = c
    end subroutine push_token

    !> A NEWLINE token, not repeated, not right after INDENT/DEDENT and not at the start.
    subroutine push_newline(lx, l, c)
        type(lexer_t), intent(inout) :: lx
        integer, intent(in) :: l, c
        if (lx%ntok == 0) return
        if (lx%tokens(lx%ntok)%kind == TOK_NEWLINE .or. lx%tokens(lx%ntok)%kind == TOK_INDENT &
            .or. lx%tokens(lx%ntok)%kind == TOK_DEDENT) return
        call push_token(lx, TOK_NEWLINE, '', l, c)
    end subroutine push_newline

    !> Newlines and indentation: a line end gives a NEWLINE outside brackets (inside them the
    !> logical line goes on) and makes the next line start with an indentation check.
    subroutine lex_line_end(lx)
        type(lexer_t), intent(inout) :: lx
        if (lx%depth == 0) call push_newline(lx, lx%line, lx%col)
        lx%i = lx%i + 1; lx%line = lx%line + 1; lx%col = 1
        ! Inside brackets the logical line goes on: no indentation to measure there, nor
        ! after the closing bracket that ends the line's brackets (`x = (1 +\n 2) * 3`).
        lx%at_line_start = lx%depth == 0
    end subroutine lex_line_end

    !> Newlines and indentation: measures the indentation of a logical line (tabs to the next
    !> multiple of 8, as Python) and emits INDENT/DEDENT tokens. Blank and comment-only lines
    !> do not count.
    !>  lx : inout, lexer state at the start of a line, left at its first non-blank
    !>  st : out, STATUS_DECK_ERROR for too many nested blocks or a dedent to a width that
    !>       no enclosing block has
    subroutine lex_indentation(lx, text, st)
        type(lexer_t), intent(inout) :: lx
        character(len=*), intent(in) :: text
        type(status_t), intent(out) :: st
        integer :: width, j, c
        width = 0; j = lx%i; c = lx%col
        do while (j <= lx%n)
            if (text(j:j) == ' ') then
                width = width + 1
            else if (text(j:j) == achar(9)) then
                width = (width / 8 + 1) * 8
            else if (text(j:j) /= achar(12)) then
                exit
            end if
            j = j + 1; c = c + 1
        end do
        lx%i = j; lx%col = c
        lx%at_line_start = .false.
        if (j > lx%n) return
        if (text(j:j) == '#' .or. text(j:j) == achar(10) .or. text(j:j) == achar(13)) then
            lx%at_line_start = .true.
            return
        end if
        if (width > lx%indents(lx%nind)) then
            if (lx%nind == MAX_INDENT_LEVELS) then
                call lex_fail(lx, st, 'blocks nested too deeply', lx%line, lx%col); return
            end if
            lx%nind = lx%nind + 1; lx%indents(lx%nind) = width
            call push_token(lx, TOK_INDENT, '', lx%line, lx%col)
        else
            do while (width < lx%indents(lx%nind))
                lx%nind = lx%nind - 1
                call push_token(lx, TOK_DEDENT, '', lx%line, lx%col)
            end do
            if (width /= lx%indents(lx%nind)) then
                call lex_fail(lx, st, 'inconsistent indentation (align with an enclosing ' // &
                              'block)', lx%line, lx%col)
            end if
        end if
    end subroutine lex_indentation

    !> Comments: skips from `#` to the end of the line (the line end itself is a token).
    subroutine skip_comment(lx, text)
        type(lexer_t), intent(inout) :: lx
        character(len=*), intent(in) :: text
        do while (lx%i <= lx%n)
            if (text(lx%i:lx%i) == achar(10)) exit
            lx%i = lx%i + 1
        end do
    end subroutine skip_comment

    !> Newlines: a backslash right before a line end (LF or CRLF) joins the two lines.
    !>  st : out, STATUS_DECK_ERROR for a backslash anywhere else
    subroutine skip_line_continuation(lx, text, st)
        type(lexer_t), intent(inout) :: lx
        character(len=*), intent(in) :: text
        type(status_t), intent(out) :: st
        integer :: i, n
        i = lx%i; n = lx%n
        if (i < n .and. text(min(i + 1, n):min(i + 1, n)) == achar(10)) then
            lx%i = i + 2; lx%line = lx%line + 1; lx%col = 1
        else if (i + 1 < n .and. &
                 text(min(i + 1, n):min(i + 2, n)) == achar(13) // achar(10)) then
            lx%i = i + 3; lx%line = lx%line + 1; lx%col = 1
        else
            call lex_fail(lx, st, 'unexpected character "\"', lx%line, lx%col)
        end if
    end subroutine skip_line_continuation

    !> Brackets: ( [ { and ) ] } are OP tokens; the nesting depth is tracked (newlines
    !> inside brackets are not tokens) and where each open bracket was, for messages.
    !>  ch : in, the bracket at text(lx%i)
    !>  st : out, STATUS_DECK_ERROR for nesting deeper than MAX_BRACKETS or a closing bracket
    !>       with none open
    subroutine lex_bracket(lx, ch, st)
        type(lexer_t), intent(inout) :: lx
        character, intent(in) :: ch
        type(status_t), intent(out) :: st
        select case (ch)
        case ('(', '[', '{')
            if (lx%depth >= MAX_BRACKETS) then
                call lex_fail(lx, st, 'brackets nested deeper than ' // to_text(MAX_BRACKETS) &
                    // ' levels (simplify the expression)', lx%line, lx%col)
                return
            end if
            lx%depth = lx%depth + 1
            lx%open_line(lx%depth) = lx%line; lx%open_col(lx%depth) = lx%col
        case default
            if (lx%depth == 0) then
                call lex_fail(lx, st, 'unmatched "' // ch // '"', lx%line, lx%col)
                return
            end if
            lx%depth = lx%depth - 1
        end select
        call push_token(lx, TOK_OP, ch, lx%line, lx%col)
        lx%i = lx%i + 1; lx%col = lx%col + 1
    end subroutine lex_bracket

    !> Names and keywords: [A-Za-z_][A-Za-z0-9_]* is a NAME token (the parser tells the
    !> keywords apart).
    subroutine lex_name(lx, text)
        type(lexer_t), intent(inout) :: lx
        character(len=*), intent(in) :: text
        integer :: j
        j = lx%i
        do while (j <= lx%n)
            if (index('abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_', &
                      text(j:j)) == 0) exit
            j = j + 1
        end do
        call push_token(lx, TOK_NAME, text(lx%i:j - 1), lx%line, lx%col)
        lx%col = lx%col + (j - lx%i); lx%i = j
    end subroutine lex_name

    !> Numbers: digits [. digits] [(e|E) [+|-] digits] is an INT token, or a REAL one when
    !> it has a dot or an exponent; the token text is the spelling.
    !>  st : out, STATUS_DECK_ERROR for an exponent without digits or a letter glued to the
    !>       number (`12abc`)
    subroutine lex_number(lx, text, st)
        type(lexer_t), intent(inout) :: lx
        character(len=*), intent(in) :: text
        type(status_t), intent(out) :: st
        integer :: i, j, n, kind
        logical :: is_real
        i = lx%i; n = lx%n
        is_real = .false.
        j = end_of_digits(text, i)
        if (j <= n) then
            if (text(j:j) == '.') then
                is_real = .true.
                j = end_of_digits(text, j + 1)
            end if
        end if
        if (j <= n) then
            if (text(j:j) == 'e' .or. text(j:j) == 'E') then
                is_real = .true.; j = j + 1
                if (j <= n) then
                    if (text(j:j) == '+' .or. text(j:j) == '-') j = j + 1
                end if
                if (.not. next_is_digit(text, j)) then
                    call lex_fail(lx, st, 'malformed number "' // text(i:j - 1) // &
                        '" (an exponent needs digits, e.g. 1.0E+03)', lx%line, lx%col)
                    return
                end if
                j = end_of_digits(text, j)
            end if
        end if
        if (j <= n) then
            if (index('abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ_', &
                      text(j:j)) > 0) then
                call lex_fail(lx, st, 'malformed number "' // text(i:j) // '"', lx%line, lx%col)
                return
            end if
        end if
        kind = TOK_INT
        if (is_real) kind = TOK_REAL
        call push_token(lx, kind, text(i:j - 1), lx%line, lx%col)
        lx%col = lx%col + (j - i); lx%i = j
    end subroutine lex_number

    !> Strings: '...', "...", '''...''', """...""" with \\ \' \" \n \t \r escapes (decoded by
    !> decode_escape), after an optional prefix: r (raw: no escapes), u, b (as plain), f (an
    !> f-string, TOK_FSTRING: its text is kept as written for the parser) and rf/fr. A
    !> STRING token holds the decoded value, located at its first character. Only
    !> triple-quoted strings may span lines; CR bytes are dropped.
    !>  st : out, STATUS_DECK_ERROR at the opening quote for an unterminated string
    subroutine lex_string(lx, text, st)
        type(lexer_t), intent(inout) :: lx
        character(len=*), intent(in) :: text
        type(status_t), intent(out) :: st
        character :: q
        logical :: triple, raw, formatted
        character(len=:), allocatable :: buf
        integer :: i, n, line, col, nb, np, k
        i = lx%i; n = lx%n; line = lx%line; col = lx%col
        np = string_prefix(text, i)
        raw = .false.; formatted = .false.
        do k = i, i + np - 1
            if (index('rR', text(k:k)) > 0) raw = .true.
            if (index('fF', text(k:k)) > 0) formatted = .true.
        end do
        i = i + np; col = col + np
        q = text(i:i)
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
                call lex_fail(lx, st, 'unterminated string: the quote opened here is never ' &
                              // 'closed', lx%line, lx%col)
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
                call lex_fail(lx, st, 'unterminated string: a quoted string ends at the end ' &
                    // 'of its line (use triple quotes for several lines)', lx%line, lx%col)
                return
            end if
            if (text(i:i) == '\' .and. i < n) then
                if (raw .or. formatted) then         ! kept as written (the quote too)
                    call append_text(buf, nb, text(i:i + 1))
                    if (text(i + 1:i + 1) == achar(10)) then
                        line = line + 1; col = -1
                    end if
                else
                    call decode_escape(text(i + 1:i + 1), buf, nb, line, col)
                end if
                i = i + 2; col = col + 2
                cycle
            end if
            if (text(i:i) == achar(10)) then
                line = line + 1; col = 0
            end if
            if (text(i:i) /= achar(13)) call append_text(buf, nb, text(i:i))
            i = i + 1; col = col + 1
        end do
        if (formatted) then
            call push_token(lx, TOK_FSTRING, buf(1:nb), lx%line, lx%col)
            lx%tokens(lx%ntok)%skip = int(np + merge(3, 1, triple), i4)
            lx%tokens(lx%ntok)%raw = raw
        else
            call push_token(lx, TOK_STRING, buf(1:nb), lx%line, lx%col)
        end if
        lx%i = i; lx%line = line; lx%col = col
    end subroutine lex_string

    !> Length of the string prefix (r, u, b, f, rb, br, rf, fr in any case) that starts at
    !> text(i) and is followed by a quote, 0 if none.
    pure integer function string_prefix(text, i) result(np)
        character(len=*), intent(in) :: text
        integer, intent(in) :: i
        integer :: k
        character(len=2) :: p
        np = 0
        do k = 1, 2
            if (i + k > len(text)) return
            if (text(i + k:i + k) == "'" .or. text(i + k:i + k) == '"') then
                p = '  '
                p(1:k) = to_lower_ascii(text(i:i + k - 1))
                select case (p)
                case ('r ', 'u ', 'b ', 'f ', 'rb', 'br', 'rf', 'fr')
                    np = k
                end select
                return
            end if
            if (index('rRuUbBfF', text(i + k:i + k)) == 0) return
        end do
    end function string_prefix

    pure function to_lower_ascii(t) result(low)
        character(len=*), intent(in) :: t
        character(len=len(t)) :: low
        integer :: k
        low = t
        do k = 1, len(t)
            if (t(k:k) >= 'A' .and. t(k:k) <= 'Z') low(k:k) = achar(iachar(t(k:k)) + 32)
        end do
    end function to_lower_ascii

    !> Strings: appends the value of the escape `\c` to buf(1:nb); unknown escapes are kept
    !> as written. A backslash before a line end joins the lines: line is advanced and col
    !> set so that the caller's col + 2 is column 1 of the next line.
    pure subroutine decode_escape(c, buf, nb, line, col)
        character, intent(in) :: c
        character(len=:), allocatable, intent(inout) :: buf
        integer, intent(inout) :: nb, line, col
        select case (c)
        case ('n')
            call append_text(buf, nb, achar(10))
        case ('t')
            call append_text(buf, nb, achar(9))
        case ('r')
            call append_text(buf, nb, achar(13))
        case ("'", '"', '\')
            call append_text(buf, nb, c)
        case (achar(10))
            line = line + 1; col = -1
        case default
            call append_text(buf, nb, '\' // c)
        end select
    end subroutine decode_escape

    !> Operators: the three- and two-character operators first (**= //= ** // <= >= == != ->
    !> += -= *= /= %=),
    !> then the one-character ones; anything else is refused.
    !>  st : out, STATUS_DECK_ERROR for a character that starts no token (non-ASCII bytes
    !>       get their own message)
    subroutine lex_operator(lx, text, st)
        type(lexer_t), intent(inout) :: lx
        character(len=*), intent(in) :: text
        type(status_t), intent(out) :: st
        character(len=2) :: two
        character(len=3) :: three
        integer :: i
        i = lx%i
        three = '   '
        if (i + 2 <= lx%n) three = text(i:i + 2)
        select case (three)
        case ('**=', '//=')
            call push_token(lx, TOK_OP, three, lx%line, lx%col)
            lx%i = i + 3; lx%col = lx%col + 3
            return
        end select
        two = '  '
        if (i + 1 <= lx%n) two = text(i:i + 1)
        select case (two)
        case ('**', '//', '<=', '>=', '==', '!=', '->', '+=', '-=', '*=', '/=', '%=')
            call push_token(lx, TOK_OP, two, lx%line, lx%col)
            lx%i = i + 2; lx%col = lx%col + 2
            return
        end select
        select case (text(i:i))
        case ('+', '-', '*', '/', '%', '<', '>', '=', ',', ':', ';', '@', '&', '|', '^', '~')
            call push_token(lx, TOK_OP, text(i:i), lx%line, lx%col)
            lx%i = i + 1; lx%col = lx%col + 1
        case default
            if (iachar(text(i:i)) >= 128) then
                call lex_fail(lx, st, 'non-ASCII character outside a string or comment ' // &
                              '(names are ASCII)', lx%line, lx%col)
            else
                call lex_fail(lx, st, 'unexpected character "' // text(i:i) // '"', lx%line, &
                              lx%col)
            end if
        end select
    end subroutine lex_operator

    !> True when text(j:j) exists and is a decimal digit.
    pure logical function next_is_digit(text, j)
        character(len=*), intent(in) :: text
        integer, intent(in) :: j
        next_is_digit = .false.
        if (j > len(text)) return
        next_is_digit = index('0123456789', text(j:j)) > 0
    end function next_is_digit

    !> Index of the first non-digit at or after j (len(text) + 1 if none).
    pure integer function end_of_digits(text, j)
        character(len=*), intent(in) :: text
        integer, intent(in) :: j
        end_of_digits = j
        do while (end_of_digits <= len(text))
            if (index('0123456789', text(end_of_digits:end_of_digits)) == 0) exit
            end_of_digits = end_of_digits + 1
        end do
    end function end_of_digits

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
