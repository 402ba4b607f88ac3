!> The expression parser (deck_parser_expr), its f-strings: the literal text of an f-string
!> token (escapes decoded unless raw, {{ and }} as braces) and its replacement fields
!> {expression[!conversion][:spec]}, each expression parsed where it stands in the deck, a
!> spec with fields of its own parsed as an f-string.
submodule(deck_parser_expr) deck_parser_fstring
    implicit none

contains

    !> The parts of f-string token `tok` added to node `owner`: literal text (escapes
    !> decoded unless raw, {{ and }} as braces) and replacement fields
    !> {expression[!conversion][:spec]}, each expression parsed where it is in the deck.
    module procedure parse_fstring
        integer :: line, col
        line = tok%line; col = tok%col + tok%skip
        call fstring_parts(p, ast, tok%text, tok%raw, 1, len(tok%text), line, col, owner, st)
    end procedure parse_fstring

    !> The parts of text(first:last) of an f-string whose text(first) is at (line, col).
    recursive subroutine fstring_parts(p, ast, text, raw, first, last, line, col, owner, st)
        type(parser_t), intent(inout) :: p
        type(ast_t), intent(inout) :: ast
        character(len=*), intent(in) :: text
        logical, intent(in) :: raw
        integer, intent(in) :: first, last
        integer, intent(inout) :: line, col
        integer, intent(in) :: owner
        type(status_t), intent(inout) :: st
        character(len=:), allocatable :: literal
        integer :: i, lit_line, lit_col, field_end, expr_end, depth, conv_at, spec_at
        integer :: node, expr, spec, l2, c2, k
        character :: q
        i = first
        literal = ''; lit_line = line; lit_col = col
        do while (i <= last)
            if (text(i:i) == '{' .and. i < last) then
                if (text(i + 1:i + 1) == '{') then
                    literal = literal // '{'; call step(2); cycle
                end if
            end if
            if (text(i:i) == '}') then
                if (i < last) then
                    if (text(i + 1:i + 1) == '}') then
                        literal = literal // '}'; call step(2); cycle
                    end if
                end if
                call fail_here('single "}" in an f-string (write "}}" for a brace)'); return
            end if
            if (text(i:i) == '\' .and. .not. raw .and. i < last) then
                literal = literal // escape_value(text(i + 1:i + 1))
                call step(2); cycle
            end if
            if (text(i:i) /= '{') then
                literal = literal // text(i:i)
                call step(1); cycle
            end if
            ! a replacement field: find where its expression ends (!, : or } at depth 0,
            ! outside quotes) and where the field ends
            call flush_literal()
            depth = 0; conv_at = 0; spec_at = 0; expr_end = 0; field_end = 0; q = ' '
            k = i + 1
            do while (k <= last)
                if (q /= ' ') then
                    if (text(k:k) == q) q = ' '
                else if (index('''"', text(k:k)) > 0) then
                    q = text(k:k)
                else if (index('([{', text(k:k)) > 0) then
                    depth = depth + 1
                else if (depth > 0 .and. index(')]}', text(k:k)) > 0) then
                    depth = depth - 1
                else if (depth == 0) then
                    if (expr_end == 0 .and. text(k:k) == '!' .and. k < last) then
                        if (text(k + 1:k + 1) /= '=') then
                            expr_end = k - 1; conv_at = k + 1
                        end if
                    else if (spec_at == 0 .and. text(k:k) == ':') then
                        if (expr_end == 0) expr_end = k - 1
                        spec_at = k + 1
                        exit
                    else if (text(k:k) == '}') then
                        if (expr_end == 0) expr_end = k - 1
                        field_end = k
                        exit
                    end if
                end if
                k = k + 1
            end do
            if (spec_at > 0) then                 ! the spec runs to the matching '}'
                depth = 0
                k = spec_at
                do while (k <= last)
                    if (text(k:k) == '{') depth = depth + 1
                    if (text(k:k) == '}') then
                        if (depth == 0) exit
                        depth = depth - 1
                    end if
                    k = k + 1
                end do
                if (k <= last) field_end = k
            end if
            if (field_end == 0) then
                call fail_here('"{" in an f-string is never closed by "}" (write "{{" for a ' &
                               // 'brace)'); return
            end if
            if (len_trim(text(i + 1:expr_end)) == 0) then
                call fail_here('empty expression in an f-string field {}'); return
            end if
            node = ast%add(N_FORMAT, '', line, col)
            call step(1)                          ! the '{'
            call field_expression(text(i:expr_end), line, col, expr)
            if (st%failed()) return
            call ast%add_kid(node, expr)
            do while (i <= expr_end)
                call step(1)
            end do
            if (conv_at > 0) then
                if (.not. good_conversion()) then
                    call step(1)
                    call fail_here('an f-string conversion is !r, !s or !a'); return
                end if
                ast%nodes(node)%text = text(conv_at:conv_at)
                call step(2)
            end if
            if (spec_at > 0) then
                call step(1)                      ! the ':'
                spec = ast%add(N_FSTRING, '', line, col)
                l2 = line; c2 = col
                call fstring_parts(p, ast, text, raw, spec_at, field_end - 1, l2, c2, spec, st)
                if (st%failed()) return
                call ast%add_kid(node, spec)
                do while (i < field_end)
                    call step(1)
                end do
            end if
            call step(1)                          ! the '}'
            call ast%add_kid(owner, node)
            lit_line = line; lit_col = col
        end do
        call flush_literal()
    contains
        !> text(conv_at) is r, s or a and is followed by ':' or '}'.
        logical function good_conversion()
            good_conversion = .false.
            if (conv_at + 1 > last) return
            if (index('rsa', text(conv_at:conv_at)) == 0) return
            good_conversion = text(conv_at + 1:conv_at + 1) == ':' .or. &
                text(conv_at + 1:conv_at + 1) == '}'
        end function good_conversion
        subroutine step(n)
            integer, intent(in) :: n
            integer :: j
            do j = 1, n
                if (i > len(text)) exit
                if (text(i:i) == achar(10)) then
                    line = line + 1; col = 1
                else
                    col = col + 1
                end if
                i = i + 1
            end do
        end subroutine step
        subroutine flush_literal()
            if (len(literal) == 0) return
            call ast%add_kid(owner, ast%add(N_STR, literal, lit_line, lit_col))
            literal = ''
        end subroutine flush_literal
        subroutine fail_here(message)
            character(len=*), intent(in) :: message
            call set_located(st, p%file, line, col, message)
        end subroutine fail_here
        !> Parses the expression text(i+1:expr_end) of a field, located in the deck.
        subroutine field_expression(field, l0, c0, id)
            character(len=*), intent(in) :: field
            integer, intent(in) :: l0, c0
            integer, intent(out) :: id
            type(parser_t) :: q2
            call tokenize(field, p%file, q2%toks, st, l0, c0)
            id = 0
            if (st%failed()) return
            q2%toks = pack(q2%toks, q2%toks%kind /= TOK_NEWLINE .and. &
                           q2%toks%kind /= TOK_INDENT .and. q2%toks%kind /= TOK_DEDENT)
            q2%file = p%file
            q2%depth = p%depth
            call parse_expr_list(q2, ast, id, st)
            if (st%failed()) return
            if (peek_kind(q2) /= TOK_EOF) call fail_at(q2, st, 'unexpected "' // &
                peek_text(q2) // '" in an f-string field')
        end subroutine field_expression
    end subroutine fstring_parts

    !> The value of the escape \c in an f-string's literal text.
    pure function escape_value(c) result(text)
        character, intent(in) :: c
        character(len=:), allocatable :: text
        select case (c)
        case ('n')
            text = achar(10)
        case ('t')
            text = achar(9)
        case ('r')
            text = achar(13)
        case ("'", '"', '\')
            text = c
        case (achar(10))
            text = ''
        case default
            text = '\' // c
        end select
    end function escape_value

    subroutine set_located(st, file, line, col, message)
        use status, only: set_error, STATUS_DECK_ERROR
        type(status_t), intent(inout) :: st
        character(len=*), intent(in) :: file, message
        integer, intent(in) :: line, col
        if (st%failed()) return
        call set_error(st, STATUS_DECK_ERROR, message, file=file, line=line, column=col)
    end subroutine set_located

end submodule deck_parser_fstring
