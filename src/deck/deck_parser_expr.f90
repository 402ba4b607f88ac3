!> Expressions of the deck language (doc/deck-language.md, "Expressions"): Python 3's
!> grammar for what decks write: conditional expressions, lambda, boolean and comparison
!> chains (in, not in, is, is not), arithmetic, unary operators, power, calls with
!> positional, keyword, *args and **kwargs arguments, subscripts and slices, attributes,
!> tuple/list/dict displays, list and dict comprehensions, generator expressions and
!> f-strings (deck_parser_fstring). What Python has and the deck language refuses (sets, bit
!> operators, the walrus) is a located error naming it.
module deck_parser_expr
    use kinds, only: i4
    use status, only: status_t
    use deck_lexer, only: token_t, tokenize, TOK_EOF, TOK_NAME, TOK_INT, TOK_REAL, TOK_STRING, &
        TOK_FSTRING, TOK_OP, TOK_NEWLINE, TOK_INDENT, TOK_DEDENT
    use deck_ast
    use deck_parser_base
    implicit none
    private
    public :: parse_expr, parse_expr_list, parse_targets, parse_or_test, parse_parameters

    interface
        !> The parts of f-string token `tok` added to node `owner` (deck_parser_fstring).
        module recursive subroutine parse_fstring(p, ast, tok, owner, st)
            type(parser_t), intent(inout) :: p
            type(ast_t), intent(inout) :: ast
            type(token_t), intent(in) :: tok
            integer, intent(in) :: owner
            type(status_t), intent(inout) :: st
        end subroutine parse_fstring
    end interface

contains

    !> expr [, expr]* [,] : a bare tuple when there is a comma (`return a, b`, `x = 1, 2`);
    !> `*x` items are allowed (`a = *b, c`).
    recursive subroutine parse_expr_list(p, ast, e, st)
        type(parser_t), intent(inout) :: p
        type(ast_t), intent(inout) :: ast
        integer, intent(out) :: e
        type(status_t), intent(inout) :: st
        integer :: first, item
        call parse_star_or_expr(p, ast, first, st)
        e = first
        if (st%failed() .or. .not. is_op(p, ',')) return
        e = ast%add(N_TUPLE, '', ast%nodes(first)%line, ast%nodes(first)%col)
        call ast%add_kid(e, first)
        do while (is_op(p, ','))
            p%pos = p%pos + 1
            if (ends_list(p)) exit
            call parse_star_or_expr(p, ast, item, st)
            if (st%failed()) return
            call ast%add_kid(e, item)
        end do
    end subroutine parse_expr_list

    !> True at a token that ends an expression list (a line end, '=', ';', ')', ':' ...).
    logical function ends_list(p)
        type(parser_t), intent(in) :: p
        ends_list = any(peek_kind(p) == [TOK_NEWLINE, TOK_EOF, TOK_DEDENT]) .or. &
            is_op(p, '=') .or. is_op(p, ';') .or. is_op(p, ')') .or. is_op(p, ']') .or. &
            is_op(p, '}') .or. is_op(p, ':') .or. is_name(p, 'in') .or. &
            (peek_kind(p) == TOK_OP .and. len(peek_text(p)) >= 2 .and. &
             index(peek_text(p), '=') == len(peek_text(p)) .and. peek_text(p) /= '==' .and. &
             peek_text(p) /= '<=' .and. peek_text(p) /= '>=' .and. peek_text(p) /= '!=')
    end function ends_list

    recursive subroutine parse_star_or_expr(p, ast, e, st)
        type(parser_t), intent(inout) :: p
        type(ast_t), intent(inout) :: ast
        integer, intent(out) :: e
        type(status_t), intent(inout) :: st
        integer :: value
        if (is_op(p, '*')) then
            e = ast%add(N_STARRED, '*', p%toks(p%pos)%line, p%toks(p%pos)%col)
            p%pos = p%pos + 1
            call parse_binary(p, ast, 1, value, st)
            if (st%failed()) return
            call ast%add_kid(e, value)
        else
            call parse_expr(p, ast, e, st)
        end if
    end subroutine parse_star_or_expr

    !> The targets of a for loop or a comprehension: expressions at the level of + and *
    !> (no comparison: `in` ends them), separated by commas: one target or a tuple.
    recursive subroutine parse_targets(p, ast, e, st)
        type(parser_t), intent(inout) :: p
        type(ast_t), intent(inout) :: ast
        integer, intent(out) :: e
        type(status_t), intent(inout) :: st
        integer :: first, item
        call parse_binary(p, ast, 1, first, st)
        e = first
        if (st%failed() .or. .not. is_op(p, ',')) return
        e = ast%add(N_TUPLE, '', ast%nodes(first)%line, ast%nodes(first)%col)
        call ast%add_kid(e, first)
        do while (is_op(p, ','))
            p%pos = p%pos + 1
            if (is_name(p, 'in')) exit
            call parse_binary(p, ast, 1, item, st)
            if (st%failed()) return
            call ast%add_kid(e, item)
        end do
    end subroutine parse_targets

    !> expr := lambda | or_test ['if' or_test 'else' expr]
    recursive subroutine parse_expr(p, ast, e, st)
        type(parser_t), intent(inout) :: p
        type(ast_t), intent(inout) :: ast
        integer, intent(out) :: e
        type(status_t), intent(inout) :: st
        integer :: cond, other, node
        e = 0
        call enter(p, st)
        if (st%failed()) return
        if (is_name(p, 'lambda')) then
            call parse_lambda(p, ast, e, st)
            call leave(p)
            return
        end if
        call parse_or_test(p, ast, e, st)
        if (st%failed()) return
        if (is_name(p, 'if')) then
            node = ast%add(N_IFEXP, 'if', p%toks(p%pos)%line, p%toks(p%pos)%col)
            p%pos = p%pos + 1
            call parse_or_test(p, ast, cond, st)
            if (st%failed()) return
            if (.not. is_name(p, 'else')) then
                call fail_at(p, st, 'conditional expression without "else" (a if c else b)')
                return
            end if
            p%pos = p%pos + 1
            call parse_expr(p, ast, other, st)
            if (st%failed()) return
            call ast%add_kid(node, e)
            call ast%add_kid(node, cond)
            call ast%add_kid(node, other)
            e = node
        end if
        if (is_op(p, ':') .and. is_op_at(p, p%pos + 1, '=')) then
            call fail_at(p, st, 'the walrus operator ":=" is not part of the deck language ' // &
                         '(assign on a line of its own)'); return
        end if
        call leave(p)
    end subroutine parse_expr

    !> lambda [params]: expr
    recursive subroutine parse_lambda(p, ast, e, st)
        type(parser_t), intent(inout) :: p
        type(ast_t), intent(inout) :: ast
        integer, intent(out) :: e
        type(status_t), intent(inout) :: st
        integer :: body
        e = ast%add(N_LAMBDA, 'lambda', p%toks(p%pos)%line, p%toks(p%pos)%col)
        p%pos = p%pos + 1
        call parse_parameters(p, ast, e, ':', st)
        if (st%failed()) return
        call expect(p, ':', st)
        if (st%failed()) return
        call parse_expr(p, ast, body, st)
        if (st%failed()) return
        call ast%add_kid(e, body)
    end subroutine parse_lambda

    !> The parameters of a def (closing ')') or a lambda (closing ':') up to `closing`:
    !> NAME, NAME=default, *NAME, **NAME, added as kids of node `owner` (deck_ast, N_DEF).
    recursive subroutine parse_parameters(p, ast, owner, closing, st)
        type(parser_t), intent(inout) :: p
        type(ast_t), intent(inout) :: ast
        integer, intent(in) :: owner
        character(len=*), intent(in) :: closing
        type(status_t), intent(inout) :: st
        integer :: param, default, kind
        logical :: seen_default, seen_star, seen_dstar
        character(len=:), allocatable :: name
        integer :: k, j
        seen_default = .false.; seen_star = .false.; seen_dstar = .false.
        do while (.not. is_op(p, closing))
            kind = N_NAME
            if (is_op(p, '*')) then
                kind = N_STARRED; p%pos = p%pos + 1
            else if (is_op(p, '**')) then
                kind = N_DSTAR; p%pos = p%pos + 1
            end if
            if (seen_dstar) then
                call fail_at(p, st, 'no parameter may follow **' // 'kwargs'); return
            end if
            if (peek_kind(p) /= TOK_NAME .or. is_keyword(peek_text(p))) then
                if (kind == N_STARRED) then
                    call fail_at(p, st, 'a bare "*" (keyword-only parameters) is not part ' // &
                                 'of the deck language'); return
                end if
                call fail_at(p, st, 'expected a parameter name, got "' // peek_text(p) // '"')
                return
            end if
            name = peek_text(p)
            do k = 1, ast%nkids(owner)
                j = ast%kid(owner, k)
                if (ast%nodes(j)%text == name) then
                    call fail_at(p, st, 'parameter ' // name // ' is named twice'); return
                end if
            end do
            param = ast%add(kind, name, p%toks(p%pos)%line, p%toks(p%pos)%col)
            p%pos = p%pos + 1
            if (is_op(p, ':') .and. closing == ')') then
                call fail_at(p, st, 'annotations (x: type) are not part of the deck language')
                return
            end if
            if (kind == N_NAME) then
                if (is_op(p, '=')) then
                    p%pos = p%pos + 1
                    call parse_expr(p, ast, default, st)
                    if (st%failed()) return
                    call ast%add_kid(param, default)
                    seen_default = .true.
                else if (seen_default .and. .not. seen_star) then
                    call fail_at(p, st, 'a parameter without default after one with a ' // &
                                 'default'); return
                end if
            else if (kind == N_STARRED) then
                if (seen_star) then
                    call fail_at(p, st, 'only one *args parameter'); return
                end if
                seen_star = .true.
            else
                seen_dstar = .true.
            end if
            call ast%add_kid(owner, param)
            if (is_op(p, ',')) then
                p%pos = p%pos + 1
            else if (.not. is_op(p, closing)) then
                call fail_at(p, st, 'expected "," or "' // closing // '" in the parameter ' // &
                             'list, got "' // peek_text(p) // '"'); return
            end if
        end do
    end subroutine parse_parameters

    !> or_test: and_test ('or' and_test)*
    recursive subroutine parse_or_test(p, ast, e, st)
        type(parser_t), intent(inout) :: p
        type(ast_t), intent(inout) :: ast
        integer, intent(out) :: e
        type(status_t), intent(inout) :: st
        call parse_bool(p, ast, N_OR, e, st)
    end subroutine parse_or_test

    !> or_test / and_test: operands joined by 'or' (kind N_OR) or 'and' (N_AND).
    recursive subroutine parse_bool(p, ast, kind, e, st)
        type(parser_t), intent(inout) :: p
        type(ast_t), intent(inout) :: ast
        integer, intent(in) :: kind
        integer, intent(out) :: e
        type(status_t), intent(inout) :: st
        integer :: item, node
        character(len=3) :: word
        word = 'or'
        if (kind == N_AND) word = 'and'
        if (kind == N_OR) then
            call parse_bool(p, ast, N_AND, e, st)
        else
            call parse_not(p, ast, e, st)
        end if
        if (st%failed() .or. .not. is_name(p, trim(word))) return
        node = ast%add(kind, trim(word), ast%nodes(e)%line, ast%nodes(e)%col)
        call ast%add_kid(node, e)
        do while (is_name(p, trim(word)))
            p%pos = p%pos + 1
            if (kind == N_OR) then
                call parse_bool(p, ast, N_AND, item, st)
            else
                call parse_not(p, ast, item, st)
            end if
            if (st%failed()) return
            call ast%add_kid(node, item)
        end do
        e = node
    end subroutine parse_bool

    recursive subroutine parse_not(p, ast, e, st)
        type(parser_t), intent(inout) :: p
        type(ast_t), intent(inout) :: ast
        integer, intent(out) :: e
        type(status_t), intent(inout) :: st
        integer :: operand
        if (is_name(p, 'not')) then
            call enter(p, st)
            if (st%failed()) return
            e = ast%add(N_UNARY, 'not', p%toks(p%pos)%line, p%toks(p%pos)%col)
            p%pos = p%pos + 1
            call parse_not(p, ast, operand, st)
            if (st%failed()) return
            call ast%add_kid(e, operand)
            call leave(p)
        else
            call parse_compare(p, ast, e, st)
        end if
    end subroutine parse_not

    !> Comparison chains; the operators are kept blank-separated in the node's text, 'not in'
    !> as 'not_in' and 'is not' as 'is_not'.
    recursive subroutine parse_compare(p, ast, e, st)
        type(parser_t), intent(inout) :: p
        type(ast_t), intent(inout) :: ast
        integer, intent(out) :: e
        type(status_t), intent(inout) :: st
        integer :: item, node
        character(len=:), allocatable :: ops, op
        call parse_binary(p, ast, 1, e, st)
        if (st%failed() .or. .not. is_compare(p)) return
        node = ast%add(N_COMPARE, '', ast%nodes(e)%line, ast%nodes(e)%col)
        call ast%add_kid(node, e)
        ops = ''
        do while (is_compare(p))
            op = peek_text(p)
            p%pos = p%pos + 1
            if (op == 'not') then
                if (.not. is_name(p, 'in')) then
                    call fail_at(p, st, 'expected "in" after "not" in a comparison'); return
                end if
                op = 'not_in'; p%pos = p%pos + 1
            else if (op == 'is' .and. is_name(p, 'not')) then
                op = 'is_not'; p%pos = p%pos + 1
            end if
            ops = ops // op // ' '
            call parse_binary(p, ast, 1, item, st)
            if (st%failed()) return
            call ast%add_kid(node, item)
        end do
        ast%nodes(node)%text = trim(ops)
        e = node
    end subroutine parse_compare

    logical function is_compare(p)
        type(parser_t), intent(in) :: p
        is_compare = is_op(p, '<') .or. is_op(p, '<=') .or. is_op(p, '>') .or. &
            is_op(p, '>=') .or. is_op(p, '==') .or. is_op(p, '!=') .or. is_name(p, 'in') &
            .or. is_name(p, 'is') .or. (is_name(p, 'not') .and. is_name_at(p, p%pos + 1, 'in'))
    end function is_compare

    !> Binary operators by level: 1 = + -, 2 = * / // %; both left-associative. The bit
    !> operators and @ are refused.
    recursive subroutine parse_binary(p, ast, level, e, st)
        type(parser_t), intent(inout) :: p
        type(ast_t), intent(inout) :: ast
        integer, intent(in) :: level
        integer, intent(out) :: e
        type(status_t), intent(inout) :: st
        integer :: right, node, chain
        if (level == 1) then
            call parse_binary(p, ast, 2, e, st)
        else
            call parse_unary(p, ast, e, st)
        end if
        if (st%failed()) return
        chain = 0
        do
            if (level == 1) then
                if (.not. (is_op(p, '+') .or. is_op(p, '-'))) exit
            else
                if (.not. (is_op(p, '*') .or. is_op(p, '/') .or. is_op(p, '//') .or. &
                           is_op(p, '%'))) exit
            end if
            node = ast%add(N_BINOP, peek_text(p), p%toks(p%pos)%line, p%toks(p%pos)%col)
            call enter(p, st)                   ! a left-deep chain is as deep as it is long
            if (st%failed()) return
            chain = chain + 1
            p%pos = p%pos + 1
            if (level == 1) then
                call parse_binary(p, ast, 2, right, st)
            else
                call parse_unary(p, ast, right, st)
            end if
            if (st%failed()) return
            call ast%add_kid(node, e)
            call ast%add_kid(node, right)
            e = node
        end do
        p%depth = p%depth - chain
        if (is_op(p, '@') .or. is_op(p, '&') .or. is_op(p, '|') .or. is_op(p, '^') .or. &
            is_op(p, '<<') .or. is_op(p, '>>')) then
            call fail_at(p, st, 'operator "' // peek_text(p) // '" is not part of the deck ' // &
                         'language (bit operators and matrix products)')
        end if
    end subroutine parse_binary

    !> unary := ('-' | '+') unary | power   (unary minus binds looser than **, as in Python)
    recursive subroutine parse_unary(p, ast, e, st)
        type(parser_t), intent(inout) :: p
        type(ast_t), intent(inout) :: ast
        integer, intent(out) :: e
        type(status_t), intent(inout) :: st
        integer :: operand
        if (is_op(p, '-') .or. is_op(p, '+')) then
            call enter(p, st)
            if (st%failed()) return
            e = ast%add(N_UNARY, peek_text(p), p%toks(p%pos)%line, p%toks(p%pos)%col)
            p%pos = p%pos + 1
            call parse_unary(p, ast, operand, st)
            if (st%failed()) return
            call ast%add_kid(e, operand)
            call leave(p)
        else if (is_op(p, '~')) then
            call fail_at(p, st, 'operator "~" is not part of the deck language'); e = 0
        else
            call parse_power(p, ast, e, st)
        end if
    end subroutine parse_unary

    !> power := primary ['**' unary]  (right-associative)
    recursive subroutine parse_power(p, ast, e, st)
        type(parser_t), intent(inout) :: p
        type(ast_t), intent(inout) :: ast
        integer, intent(out) :: e
        type(status_t), intent(inout) :: st
        integer :: node, exponent
        call parse_primary(p, ast, e, st)
        if (st%failed() .or. .not. is_op(p, '**')) return
        node = ast%add(N_BINOP, '**', p%toks(p%pos)%line, p%toks(p%pos)%col)
        call enter(p, st)
        if (st%failed()) return
        p%pos = p%pos + 1
        call parse_unary(p, ast, exponent, st)
        if (st%failed()) return
        call leave(p)
        call ast%add_kid(node, e)
        call ast%add_kid(node, exponent)
        e = node
    end subroutine parse_power

    !> atom followed by attributes `.name`, calls `( ... )` and subscripts `[ ... ]`;
    !> `math.NAME` becomes the name 'math.NAME' (FORMULE and the built-in math functions).
    recursive subroutine parse_primary(p, ast, e, st)
        type(parser_t), intent(inout) :: p
        type(ast_t), intent(inout) :: ast
        integer, intent(out) :: e
        type(status_t), intent(inout) :: st
        integer :: node, chain
        call parse_atom(p, ast, e, st)
        if (st%failed()) return
        chain = 0
        do
            if (.not. (is_op(p, '.') .or. is_op(p, '(') .or. is_op(p, '['))) exit
            call enter(p, st)                    ! f()()..., x[0][0]..., a.b.c chain as deep
            if (st%failed()) return
            chain = chain + 1
            if (is_op(p, '.')) then
                if (peek_kind_at(p, p%pos + 1) /= TOK_NAME) then
                    p%pos = p%pos + 1
                    call fail_at(p, st, 'expected an attribute name after "."'); return
                end if
                if (ast%nodes(e)%kind == N_NAME .and. ast%nodes(e)%text == 'math') then
                    ast%nodes(e)%text = 'math.' // p%toks(p%pos + 1)%text
                    p%pos = p%pos + 2
                    cycle
                end if
                node = ast%add(N_ATTR, p%toks(p%pos + 1)%text, p%toks(p%pos + 1)%line, &
                               p%toks(p%pos + 1)%col)
                call ast%add_kid(node, e)
                e = node
                p%pos = p%pos + 2
            else if (is_op(p, '(')) then
                node = ast%add(N_CALL, '', p%toks(p%pos)%line, p%toks(p%pos)%col)
                call ast%add_kid(node, e)
                call parse_arguments(p, ast, node, st)
                if (st%failed()) return
                e = node
            else
                call parse_subscript(p, ast, e, st)
                if (st%failed()) return
            end if
        end do
        p%depth = p%depth - chain
    end subroutine parse_primary

    !> e[index], e[i, j] (the index is a tuple) or a slice e[start:stop:step] (each part
    !> optional).
    recursive subroutine parse_subscript(p, ast, e, st)
        type(parser_t), intent(inout) :: p
        type(ast_t), intent(inout) :: ast
        integer, intent(inout) :: e
        type(status_t), intent(inout) :: st
        integer :: node, part(3), k, line, col, extra
        character(len=3) :: parts
        line = p%toks(p%pos)%line; col = p%toks(p%pos)%col
        p%pos = p%pos + 1
        parts = '000'; part = 0
        if (is_op(p, ']')) then
            call fail_at(p, st, 'empty subscript [] (give an index, e.g. x[0], or a slice ' // &
                         'x[1:3])'); return
        end if
        if (.not. is_op(p, ':')) then
            call parse_expr(p, ast, part(1), st)
            if (st%failed()) return
            parts(1:1) = '1'
            if (is_op(p, ',')) then              ! x[i, j]: the index is the tuple (i, j)
                call tuple_index(part(1))
                if (st%failed()) return
            end if
            if (is_op(p, ']')) then
                p%pos = p%pos + 1
                node = ast%add(N_INDEX, '[]', line, col)
                call ast%add_kid(node, e)
                call ast%add_kid(node, part(1))
                e = node
                return
            end if
            if (.not. is_op(p, ':')) then
                call fail_at(p, st, 'expected "]" or ":" in the subscript, got "' // &
                             peek_text(p) // '"'); return
            end if
        end if
        p%pos = p%pos + 1                        ! the first ':'
        if (.not. (is_op(p, ':') .or. is_op(p, ']') .or. is_op(p, ','))) then
            call parse_expr(p, ast, part(2), st)
            if (st%failed()) return
            parts(2:2) = '1'
        end if
        if (is_op(p, ':')) then
            p%pos = p%pos + 1
            if (.not. (is_op(p, ']') .or. is_op(p, ','))) then
                call parse_expr(p, ast, part(3), st)
                if (st%failed()) return
                parts(3:3) = '1'
            end if
        end if
        if (is_op(p, ',')) then                  ! x[a:b, c]: a slice inside a tuple index
            extra = ast%add(N_SLICEITEM, parts, line, col)
            do k = 1, 3
                if (parts(k:k) == '1') call ast%add_kid(extra, part(k))
            end do
            call tuple_index(extra)
            if (st%failed()) return
            node = ast%add(N_INDEX, '[]', line, col)
            call ast%add_kid(node, e)
            call ast%add_kid(node, extra)
            e = node
            p%pos = p%pos + 1
            return
        end if
        call expect(p, ']', st)
        if (st%failed()) return
        node = ast%add(N_SLICE, parts, line, col)
        call ast%add_kid(node, e)
        do k = 1, 3
            if (parts(k:k) == '1') call ast%add_kid(node, part(k))
        end do
        e = node
    contains
        !> The items after the first of a tuple index (, i, a:b, ...) up to ']': first
        !> becomes the tuple's node.
        recursive subroutine tuple_index(first)
            integer, intent(inout) :: first
            integer :: tuple, item, q(3), j
            character(len=3) :: qparts
            tuple = ast%add(N_TUPLE, '', ast%nodes(first)%line, ast%nodes(first)%col)
            call ast%add_kid(tuple, first)
            do while (is_op(p, ','))
                p%pos = p%pos + 1
                if (is_op(p, ']')) exit
                qparts = '000'; q = 0
                if (.not. is_op(p, ':')) then
                    call parse_expr(p, ast, q(1), st)
                    if (st%failed()) return
                    qparts(1:1) = '1'
                end if
                if (is_op(p, ':')) then
                    p%pos = p%pos + 1
                    if (.not. (is_op(p, ':') .or. is_op(p, ']') .or. is_op(p, ','))) then
                        call parse_expr(p, ast, q(2), st)
                        if (st%failed()) return
                        qparts(2:2) = '1'
                    end if
                    if (is_op(p, ':')) then
                        p%pos = p%pos + 1
                        if (.not. (is_op(p, ']') .or. is_op(p, ','))) then
                            call parse_expr(p, ast, q(3), st)
                            if (st%failed()) return
                            qparts(3:3) = '1'
                        end if
                    end if
                    item = ast%add(N_SLICEITEM, qparts, p%toks(p%pos)%line, p%toks(p%pos)%col)
                    do j = 1, 3
                        if (qparts(j:j) == '1') call ast%add_kid(item, q(j))
                    end do
                else
                    item = q(1)
                end if
                call ast%add_kid(tuple, item)
            end do
            if (.not. is_op(p, ']')) then
                call fail_at(p, st, 'expected "]" after the index, got "' // peek_text(p) // '"')
                return
            end if
            first = tuple
        end subroutine tuple_index
    end subroutine parse_subscript

    !> ( [arg | NAME=expr | *expr | **expr] , ... ) — positional arguments before keyword
    !> ones; a generator expression may be the only argument: sum(x for x in L).
    recursive subroutine parse_arguments(p, ast, call_node, st)
        type(parser_t), intent(inout) :: p
        type(ast_t), intent(inout) :: ast
        integer, intent(in) :: call_node
        type(status_t), intent(inout) :: st
        integer :: arg, kw, nargs, gen
        logical :: seen_keyword
        p%pos = p%pos + 1
        seen_keyword = .false.
        nargs = 0
        do while (.not. is_op(p, ')'))
            nargs = nargs + 1
            if (is_op(p, '**')) then
                kw = ast%add(N_DSTAR, '**', p%toks(p%pos)%line, p%toks(p%pos)%col)
                p%pos = p%pos + 1
                call parse_expr(p, ast, arg, st)
                if (st%failed()) return
                call ast%add_kid(kw, arg)
                call ast%add_kid(call_node, kw)
                seen_keyword = .true.
            else if (is_op(p, '*')) then
                kw = ast%add(N_STARRED, '*', p%toks(p%pos)%line, p%toks(p%pos)%col)
                p%pos = p%pos + 1
                call parse_expr(p, ast, arg, st)
                if (st%failed()) return
                call ast%add_kid(kw, arg)
                call ast%add_kid(call_node, kw)
            else if (peek_kind(p) == TOK_NAME .and. is_op_at(p, p%pos + 1, '=')) then
                kw = ast%add(N_KWARG, peek_text(p), p%toks(p%pos)%line, p%toks(p%pos)%col)
                p%pos = p%pos + 2
                call parse_expr(p, ast, arg, st)
                if (st%failed()) return
                call ast%add_kid(kw, arg)
                call ast%add_kid(call_node, kw)
                seen_keyword = .true.
            else
                if (seen_keyword) then
                    call fail_at(p, st, 'positional argument after keyword arguments'); return
                end if
                call parse_expr(p, ast, arg, st)
                if (st%failed()) return
                if (is_name(p, 'for')) then
                    if (nargs > 1) then
                        call fail_at(p, st, 'a generator expression as an argument must be ' &
                                     // 'the only one (or in parentheses)'); return
                    end if
                    gen = ast%add(N_GENEXP, '', ast%nodes(arg)%line, ast%nodes(arg)%col)
                    call ast%add_kid(gen, arg)
                    call parse_comp_fors(p, ast, gen, st)
                    if (st%failed()) return
                    if (.not. is_op(p, ')')) then
                        call fail_at(p, st, 'a generator expression as an argument must be ' &
                                     // 'the only one (or in parentheses)'); return
                    end if
                    arg = gen
                end if
                call ast%add_kid(call_node, arg)
            end if
            if (is_op(p, ',')) then
                p%pos = p%pos + 1
            else if (.not. is_op(p, ')')) then
                call fail_at(p, st, 'expected "," or ")" in the argument list, got "' // &
                             peek_text(p) // '"'); return
            end if
        end do
        p%pos = p%pos + 1
    end subroutine parse_arguments

    !> One or more `for TARGETS in ITERABLE [if COND]...` clauses of a comprehension, added
    !> to node `owner` as N_COMPFOR nodes.
    recursive subroutine parse_comp_fors(p, ast, owner, st)
        type(parser_t), intent(inout) :: p
        type(ast_t), intent(inout) :: ast
        integer, intent(in) :: owner
        type(status_t), intent(inout) :: st
        integer :: clause, target, iterable, cond
        do while (is_name(p, 'for'))
            clause = ast%add(N_COMPFOR, 'for', p%toks(p%pos)%line, p%toks(p%pos)%col)
            p%pos = p%pos + 1
            call parse_targets(p, ast, target, st)
            if (st%failed()) return
            if (.not. is_name(p, 'in')) then
                call fail_at(p, st, 'expected "in" in the comprehension, got "' // &
                             peek_text(p) // '"'); return
            end if
            p%pos = p%pos + 1
            call parse_or_test(p, ast, iterable, st)
            if (st%failed()) return
            call ast%add_kid(clause, target)
            call ast%add_kid(clause, iterable)
            do while (is_name(p, 'if'))
                p%pos = p%pos + 1
                call parse_or_test(p, ast, cond, st)
                if (st%failed()) return
                call ast%add_kid(clause, cond)
            end do
            call ast%add_kid(owner, clause)
        end do
    end subroutine parse_comp_fors

    recursive subroutine parse_atom(p, ast, e, st)
        type(parser_t), intent(inout) :: p
        type(ast_t), intent(inout) :: ast
        integer, intent(out) :: e
        type(status_t), intent(inout) :: st
        integer :: line, col
        e = 0
        line = p%toks(p%pos)%line; col = p%toks(p%pos)%col
        select case (peek_kind(p))
        case (TOK_INT)
            e = ast%add(N_INT, peek_text(p), line, col); p%pos = p%pos + 1
        case (TOK_REAL)
            e = ast%add(N_REAL, peek_text(p), line, col); p%pos = p%pos + 1
        case (TOK_STRING, TOK_FSTRING)
            call parse_strings(p, ast, e, st)
        case (TOK_NAME)
            select case (peek_text(p))
            case ('def', 'if', 'return', 'pass', 'and', 'or', 'else', 'elif', 'in', 'is', &
                  'for', 'while', 'import', 'from', 'class', 'del', 'global', 'nonlocal', &
                  'with', 'try', 'except', 'finally', 'raise', 'assert', 'yield', 'async', &
                  'await', 'break', 'continue', 'as', 'not', 'lambda')
                call fail_at(p, st, 'unexpected keyword "' // peek_text(p) // &
                             '" inside an expression'); return
            end select
            e = ast%add(N_NAME, peek_text(p), line, col); p%pos = p%pos + 1
        case (TOK_OP)
            select case (peek_text(p))
            case ('(')
                call parse_display(p, ast, ')', N_TUPLE, e, st)
            case ('[')
                call parse_display(p, ast, ']', N_LIST, e, st)
            case ('{')
                call parse_dict(p, ast, e, st)
            case default
                call fail_at(p, st, 'unexpected "' // peek_text(p) // '" (expected a value)')
            end select
        case (TOK_EOF)
            call fail_at(p, st, 'unexpected end of file (an expression is incomplete)')
        case default
            call fail_at(p, st, 'unexpected end of line (an expression is incomplete)')
        end select
    end subroutine parse_atom

    !> Adjacent string literals are one string ('a' 'b' is 'ab'); with an f-string among
    !> them, an N_FSTRING of their parts.
    recursive subroutine parse_strings(p, ast, e, st)
        type(parser_t), intent(inout) :: p
        type(ast_t), intent(inout) :: ast
        integer, intent(out) :: e
        type(status_t), intent(inout) :: st
        integer :: line, col, k
        logical :: any_f
        line = p%toks(p%pos)%line; col = p%toks(p%pos)%col
        any_f = .false.
        k = p%pos
        do while (peek_kind_at(p, k) == TOK_STRING .or. peek_kind_at(p, k) == TOK_FSTRING)
            if (peek_kind_at(p, k) == TOK_FSTRING) any_f = .true.
            k = k + 1
        end do
        if (.not. any_f) then
            e = ast%add(N_STR, '', line, col)
            do while (peek_kind(p) == TOK_STRING)
                ast%nodes(e)%text = ast%nodes(e)%text // p%toks(p%pos)%text
                p%pos = p%pos + 1
            end do
            return
        end if
        e = ast%add(N_FSTRING, '', line, col)
        do while (p%pos < k)
            if (peek_kind(p) == TOK_STRING) then
                call ast%add_kid(e, ast%add(N_STR, p%toks(p%pos)%text, p%toks(p%pos)%line, &
                                            p%toks(p%pos)%col))
            else
                call parse_fstring(p, ast, p%toks(p%pos), e, st)
                if (st%failed()) return
            end if
            p%pos = p%pos + 1
        end do
    end subroutine parse_strings

    !> '(' ... ')' or '[' ... ']': a parenthesized expression, a tuple, a list, a list
    !> comprehension or a generator expression; `*x` items unpack.
    recursive subroutine parse_display(p, ast, closing, kind, e, st)
        type(parser_t), intent(inout) :: p
        type(ast_t), intent(inout) :: ast
        character(len=1), intent(in) :: closing
        integer, intent(in) :: kind
        integer, intent(out) :: e
        type(status_t), intent(inout) :: st
        integer :: item, node, count, comp
        logical :: trailing_comma, starred
        node = ast%add(kind, '', p%toks(p%pos)%line, p%toks(p%pos)%col)
        e = node
        p%pos = p%pos + 1
        count = 0; trailing_comma = .false.; starred = .false.
        do while (.not. is_op(p, closing))
            call parse_star_or_expr(p, ast, item, st)
            if (st%failed()) return
            if (ast%nodes(item)%kind == N_STARRED) starred = .true.
            if (is_name(p, 'for')) then
                if (count > 0 .or. ast%nodes(item)%kind == N_STARRED) then
                    call fail_at(p, st, 'a comprehension holds one element expression'); return
                end if
                comp = ast%add(merge(N_LISTCOMP, N_GENEXP, kind == N_LIST), '', &
                               ast%nodes(node)%line, ast%nodes(node)%col)
                call ast%add_kid(comp, item)
                call parse_comp_fors(p, ast, comp, st)
                if (st%failed()) return
                call expect(p, closing, st)
                e = comp
                return
            end if
            call ast%add_kid(node, item)
            count = count + 1
            trailing_comma = .false.
            if (is_op(p, ',')) then
                p%pos = p%pos + 1; trailing_comma = .true.
            else if (.not. is_op(p, closing)) then
                call fail_at(p, st, 'expected "," or "' // closing // '", got "' // &
                             peek_text(p) // '" (missing comma?)'); return
            end if
        end do
        p%pos = p%pos + 1
        if (kind == N_TUPLE .and. count == 1 .and. .not. trailing_comma .and. .not. starred) then
            e = item                              ! (x) is x, (x,) is a 1-tuple
        end if
    end subroutine parse_display

    !> '{' ... '}': a dict display {k: v, **d, ...} or a dict comprehension {k: v for ...};
    !> sets are refused.
    recursive subroutine parse_dict(p, ast, e, st)
        type(parser_t), intent(inout) :: p
        type(ast_t), intent(inout) :: ast
        integer, intent(out) :: e
        type(status_t), intent(inout) :: st
        integer :: key, value, node, comp, star
        node = ast%add(N_DICT, '', p%toks(p%pos)%line, p%toks(p%pos)%col)
        e = node
        p%pos = p%pos + 1
        do while (.not. is_op(p, '}'))
            if (is_op(p, '**')) then
                star = ast%add(N_DSTAR, '**', p%toks(p%pos)%line, p%toks(p%pos)%col)
                p%pos = p%pos + 1
                call parse_binary(p, ast, 1, value, st)
                if (st%failed()) return
                call ast%add_kid(star, value)
                call ast%add_kid(node, star)
                call ast%add_kid(node, star)
            else
                call parse_expr(p, ast, key, st)
                if (st%failed()) return
                if (.not. is_op(p, ':')) then
                    call fail_at(p, st, 'sets { } are not part of the deck language (a ' // &
                        'dict is {KEY: VALUE, ...}; a list [ ... ] or a tuple ( ... ) hold ' // &
                        'values)'); return
                end if
                p%pos = p%pos + 1
                call parse_expr(p, ast, value, st)
                if (st%failed()) return
                if (is_name(p, 'for')) then
                    if (ast%nkids(node) > 0) then
                        call fail_at(p, st, 'a dict comprehension holds one KEY: VALUE'); return
                    end if
                    comp = ast%add(N_DICTCOMP, '', ast%nodes(node)%line, ast%nodes(node)%col)
                    call ast%add_kid(comp, key)
                    call ast%add_kid(comp, value)
                    call parse_comp_fors(p, ast, comp, st)
                    if (st%failed()) return
                    call expect(p, '}', st)
                    e = comp
                    return
                end if
                call ast%add_kid(node, key)
                call ast%add_kid(node, value)
            end if
            if (is_op(p, ',')) then
                p%pos = p%pos + 1
            else if (.not. is_op(p, '}')) then
                call fail_at(p, st, 'expected "," or "}" in the dict, got "' // &
                             peek_text(p) // '"'); return
            end if
        end do
        p%pos = p%pos + 1
    end subroutine parse_dict

end module deck_parser_expr
