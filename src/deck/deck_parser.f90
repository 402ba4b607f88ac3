!> Recursive-descent parser of the deck language (doc/deck-language.md) to a deck_ast tree:
!> the statements here, the expressions in deck_parser_expr, the shared state and token
!> helpers in deck_parser_base. Constructs outside the language are refused with a message
!> naming them. Recursion is bounded by MAX_DEPTH so no input can overflow the stack.
module deck_parser
    use status, only: status_t, set_error, STATUS_DECK_ERROR
    use deck_lexer, only: tokenize, TOK_EOF, TOK_NAME, TOK_NEWLINE, TOK_INDENT, TOK_DEDENT
    use deck_ast
    use deck_parser_base
    use deck_parser_expr, only: parse_expr, parse_expr_list, parse_targets, parse_parameters
    implicit none
    private

    public :: parse_deck, parse_expression, MAX_DEPTH

contains

    !> Parses a whole deck.
    !>  text : in, the deck text;  file : in, its name for messages
    !>  ast  : inout, nodes are appended; ast%root is set to the N_MODULE node
    !>  st   : out, STATUS_DECK_ERROR located at the offending token
    subroutine parse_deck(text, file, ast, st)
        character(len=*), intent(in) :: text, file
        type(ast_t), intent(inout) :: ast
        type(status_t), intent(out) :: st
        type(parser_t) :: p
        integer :: root, first
        p%file = file
        first = ast%n + 1
        call tokenize(text, file, p%toks, st)
        if (st%failed()) return
        call ast%use_file(file)
        root = ast%add(N_MODULE, file, 1, 1)
        do
            call skip_newlines(p)
            if (peek_kind(p) == TOK_EOF) exit
            if (peek_kind(p) == TOK_INDENT) then
                call fail_at(p, st, 'unexpected indentation (a statement at top level ' // &
                             'starts in column 1)')
                return
            end if
            call parse_statement_line(p, ast, root, st)
            if (st%failed()) return
        end do
        ast%root = root
        ast%nodes(root)%end_line = p%toks(size(p%toks))%line
        call ast%seal(first)
    end subroutine parse_deck

    !> Parses one expression held in a string (FORMULE VALE).
    !>  text : in, the expression;  file : in, deck name;  line0, col0 : in, where text(1:1)
    !>  sits in the deck;  ast : inout;  expr : out, node of the expression;  st : out
    subroutine parse_expression(text, file, line0, col0, ast, expr, st)
        character(len=*), intent(in) :: text, file
        integer, intent(in) :: line0, col0
        type(ast_t), intent(inout) :: ast
        integer, intent(out) :: expr
        type(status_t), intent(out) :: st
        type(parser_t) :: p
        integer :: first
        expr = 0
        p%file = file
        first = ast%n + 1
        call tokenize(text, file, p%toks, st, line0, col0)
        if (st%failed()) return
        call ast%use_file(file)
        ! A VALE string may span lines (triple quotes): line ends and indentation inside it
        ! are insignificant, as inside brackets.
        p%toks = pack(p%toks, p%toks%kind /= TOK_NEWLINE .and. p%toks%kind /= TOK_INDENT &
                      .and. p%toks%kind /= TOK_DEDENT)
        call skip_layout(p)
        if (peek_kind(p) == TOK_EOF) then
            call fail_at(p, st, 'empty expression (give a formula, e.g. ''2.0*X'')')
            return
        end if
        call parse_expr(p, ast, expr, st)
        if (st%failed()) return
        call skip_layout(p)
        if (peek_kind(p) /= TOK_EOF) call fail_at(p, st, 'unexpected "' // &
            peek_text(p) // '" after the end of the expression')
        call ast%seal(first)
    contains
        subroutine skip_layout(q)
            type(parser_t), intent(inout) :: q
            do while (any(peek_kind(q) == [TOK_NEWLINE, TOK_INDENT, TOK_DEDENT]))
                q%pos = q%pos + 1
            end do
        end subroutine skip_layout
    end subroutine parse_expression

    ! ---- statements -------------------------------------------------------------------------

    !> Simple statements separated by ';' up to a NEWLINE, or one compound statement.
    recursive subroutine parse_statement_line(p, ast, block, st)
        type(parser_t), intent(inout) :: p
        type(ast_t), intent(inout) :: ast
        integer, intent(in) :: block
        type(status_t), intent(inout) :: st
        integer :: stmt
        if (is_name(p, 'def') .or. is_name(p, 'if') .or. is_name(p, 'for') .or. &
            is_name(p, 'while')) then
            call enter(p, st)
            if (st%failed()) return
            if (is_name(p, 'def')) then
                call parse_def(p, ast, stmt, st)
            else if (is_name(p, 'for')) then
                call parse_for(p, ast, stmt, st)
            else if (is_name(p, 'while')) then
                call parse_while(p, ast, stmt, st)
            else
                call parse_if(p, ast, stmt, st)
            end if
            call leave(p)
            if (st%failed()) return
            call ast%add_kid(block, stmt)
            return
        end if
        do
            call parse_simple(p, ast, stmt, st)
            if (st%failed()) return
            call ast%add_kid(block, stmt)
            if (is_op(p, ';')) then
                p%pos = p%pos + 1
                if (any(peek_kind(p) == [TOK_NEWLINE, TOK_EOF])) exit
                cycle
            end if
            exit
        end do
        select case (peek_kind(p))
        case (TOK_NEWLINE)
            p%pos = p%pos + 1
        case (TOK_EOF, TOK_DEDENT)
        case default
            call fail_at(p, st, 'unexpected "' // peek_text(p) // '" (a statement ends ' // &
                'at the end of the line or at ";"; missing comma or operator?)')
        end select
    end subroutine parse_statement_line

    !> Assignment (also to several targets, to subscripts and attributes, unpacking),
    !> augmented assignment, expression statement, import, del, assert, raise, return,
    !> pass, break, continue.
    recursive subroutine parse_simple(p, ast, stmt, st)
        type(parser_t), intent(inout) :: p
        type(ast_t), intent(inout) :: ast
        integer, intent(out) :: stmt
        type(status_t), intent(inout) :: st
        integer :: e, value, line, col
        integer, allocatable :: targets(:)
        character(len=:), allocatable :: op
        integer :: k
        stmt = 0
        line = p%toks(p%pos)%line; col = p%toks(p%pos)%col
        if (is_name(p, 'import') .or. is_name(p, 'from')) then
            call parse_import(p, ast, stmt, st)
            if (st%ok()) ast%nodes(stmt)%end_line = p%toks(max(1, p%pos - 1))%line
            return
        end if
        if (is_name(p, 'break') .or. is_name(p, 'continue')) then
            if (p%loop_depth == 0) then
                call fail_at(p, st, '"' // peek_text(p) // '" outside a loop'); return
            end if
            stmt = ast%add(merge(N_BREAK, N_CONTINUE, is_name(p, 'break')), peek_text(p), &
                           line, col)
            p%pos = p%pos + 1
            return
        end if
        call refuse_keywords(p, st)
        if (st%failed()) return
        select case (peek_text(p))
        case ('return')
            if (peek_kind(p) == TOK_NAME) then
                if (p%def_depth == 0) then
                    call fail_at(p, st, '"return" outside a def'); return
                end if
                p%pos = p%pos + 1
                stmt = ast%add(N_RETURN, 'return', line, col)
                if (any(peek_kind(p) == [TOK_NEWLINE, TOK_EOF, TOK_DEDENT]) .or. &
                    is_op(p, ';')) then
                    call ast%add_kid(stmt, ast%add(N_NAME, 'None', line, col))
                    return
                end if
                call parse_expr_list(p, ast, e, st)
                if (st%failed()) return
                call ast%add_kid(stmt, e)
                return
            end if
        case ('pass')
            if (peek_kind(p) == TOK_NAME) then
                p%pos = p%pos + 1
                stmt = ast%add(N_PASS, 'pass', line, col)
                return
            end if
        case ('del', 'assert', 'raise')
            if (peek_kind(p) == TOK_NAME) then
                call parse_keyword_statement(p, ast, stmt, st)
                return
            end if
        end select
        call parse_expr_list(p, ast, e, st)
        if (st%failed()) return
        if (is_op(p, '=')) then
            allocate (targets(0))
            do while (is_op(p, '='))
                call check_target(p, ast, e, st)
                if (st%failed()) return
                targets = [targets, e]
                p%pos = p%pos + 1
                call parse_expr_list(p, ast, e, st)
                if (st%failed()) return
            end do
            value = e
            if (size(targets) == 1 .and. ast%nodes(targets(1))%kind == N_NAME) then
                stmt = ast%add(N_ASSIGN, ast%nodes(targets(1))%text, line, col)
            else
                stmt = ast%add(N_ASSIGN_MULTI, '=', line, col)
                do k = 1, size(targets)
                    call ast%add_kid(stmt, targets(k))
                end do
            end if
            call ast%add_kid(stmt, value)
        else if (is_augmented(p)) then
            op = peek_text(p)
            op = op(1:len(op) - 1)
            select case (ast%nodes(e)%kind)
            case (N_NAME, N_INDEX, N_ATTR)
                call check_target(p, ast, e, st)
                if (st%failed()) return
            case default
                call fail_node(ast, e, st, 'cannot use ' // op // '= on ' // &
                    target_word(ast, e) // ' (a name, x[i] or x.attr)'); return
            end select
            stmt = ast%add(N_AUGASSIGN, op, p%toks(p%pos)%line, p%toks(p%pos)%col)
            p%pos = p%pos + 1
            call parse_expr_list(p, ast, value, st)
            if (st%failed()) return
            call ast%add_kid(stmt, e)
            call ast%add_kid(stmt, value)
            ast%nodes(stmt)%line = line; ast%nodes(stmt)%col = col
        else
            stmt = ast%add(N_EXPR, '', line, col)
            call ast%add_kid(stmt, e)
        end if
        ast%nodes(stmt)%end_line = p%toks(max(1, p%pos - 1))%line
    end subroutine parse_simple

    logical function is_augmented(p)
        type(parser_t), intent(in) :: p
        is_augmented = is_op(p, '+=') .or. is_op(p, '-=') .or. is_op(p, '*=') .or. &
            is_op(p, '/=') .or. is_op(p, '//=') .or. is_op(p, '%=') .or. is_op(p, '**=')
    end function is_augmented

    !> Expression `e` can be assigned to: a name, x[i], x[i:j], x.attr, or a tuple/list of
    !> targets (unpacking); else a located error naming what it is.
    recursive subroutine check_target(p, ast, e, st)
        type(parser_t), intent(inout) :: p
        type(ast_t), intent(inout) :: ast
        integer, intent(in) :: e
        type(status_t), intent(inout) :: st
        integer :: k
        select case (ast%nodes(e)%kind)
        case (N_NAME)
            select case (ast%nodes(e)%text)
            case ('None', 'True', 'False')
                call fail_node(ast, e, st, 'cannot assign to ' // ast%nodes(e)%text)
            case default
                if (index(ast%nodes(e)%text, '.') > 0) call fail_node(ast, e, st, &
                    'cannot assign to ' // ast%nodes(e)%text // ' (a built-in math name)')
            end select
        case (N_INDEX, N_SLICE, N_ATTR)
        case (N_TUPLE, N_LIST)
            if (ast%nkids(e) == 0) then
                call fail_node(ast, e, st, 'cannot assign to an empty ' // target_word(ast, e))
                return
            end if
            do k = 1, ast%nkids(e)
                call check_target(p, ast, ast%kid(e, k), st)
                if (st%failed()) return
            end do
        case (N_STARRED)
            call fail_node(ast, e, st, 'starred targets (a, *rest = ...) are not part of ' // &
                'the deck language (slice instead: a, rest = L[0], L[1:])')
        case default
            call fail_node(ast, e, st, 'cannot assign to ' // target_word(ast, e) // &
                ' (a name, x[i], x.attr or a tuple of them); is "=" meant to be "=="?')
        end select
    end subroutine check_target

    !> What an expression node is, in words, for messages.
    function target_word(ast, e) result(word)
        type(ast_t), intent(in) :: ast
        integer, intent(in) :: e
        character(len=:), allocatable :: word
        select case (ast%nodes(e)%kind)
        case (N_CALL)
            word = 'a call'
        case (N_INT, N_REAL)
            word = 'a number'
        case (N_STR, N_FSTRING)
            word = 'a string'
        case (N_TUPLE)
            word = 'tuple'
        case (N_LIST)
            word = 'list'
        case (N_COMPARE)
            word = 'a comparison'
        case (N_BINOP, N_UNARY)
            word = 'an operation'
        case default
            word = 'this expression'
        end select
    end function target_word

    subroutine fail_node(ast, e, st, message)
        type(ast_t), intent(in) :: ast
        integer, intent(in) :: e
        type(status_t), intent(inout) :: st
        character(len=*), intent(in) :: message
        if (st%failed()) return
        call set_error(st, STATUS_DECK_ERROR, message, file=ast%file_name(e), &
                       line=ast%nodes(e)%line, column=ast%nodes(e)%col)
    end subroutine fail_node

    !> del TARGETS | assert COND [, MESSAGE] | raise [EXCEPTION]
    recursive subroutine parse_keyword_statement(p, ast, stmt, st)
        type(parser_t), intent(inout) :: p
        type(ast_t), intent(inout) :: ast
        integer, intent(out) :: stmt
        type(status_t), intent(inout) :: st
        integer :: e, k, line, col
        character(len=:), allocatable :: word
        word = peek_text(p)
        line = p%toks(p%pos)%line; col = p%toks(p%pos)%col
        p%pos = p%pos + 1
        select case (word)
        case ('del')
            stmt = ast%add(N_DEL, 'del', line, col)
            call parse_expr_list(p, ast, e, st)
            if (st%failed()) return
            if (ast%nodes(e)%kind == N_TUPLE) then
                do k = 1, ast%nkids(e)
                    call del_target(ast%kid(e, k))
                    if (st%failed()) return
                end do
            else
                call del_target(e)
            end if
        case ('assert')
            stmt = ast%add(N_ASSERT, 'assert', line, col)
            call parse_expr(p, ast, e, st)
            if (st%failed()) return
            call ast%add_kid(stmt, e)
            if (is_op(p, ',')) then
                p%pos = p%pos + 1
                call parse_expr(p, ast, e, st)
                if (st%failed()) return
                call ast%add_kid(stmt, e)
            end if
        case default
            stmt = ast%add(N_RAISE, 'raise', line, col)
            if (.not. (any(peek_kind(p) == [TOK_NEWLINE, TOK_EOF, TOK_DEDENT]) .or. &
                       is_op(p, ';'))) then
                call parse_expr(p, ast, e, st)
                if (st%failed()) return
                call ast%add_kid(stmt, e)
                if (is_name(p, 'from')) then
                    call fail_at(p, st, '"raise ... from" is not part of the deck language')
                    return
                end if
            end if
        end select
        ast%nodes(stmt)%end_line = p%toks(max(1, p%pos - 1))%line
    contains
        subroutine del_target(t)
            integer, intent(in) :: t
            select case (ast%nodes(t)%kind)
            case (N_NAME, N_INDEX, N_SLICE)
                call ast%add_kid(stmt, t)
            case default
                call fail_node(ast, t, st, 'del takes names and subscripts (del x, del L[i], ' &
                               // 'del d[k])')
            end select
        end subroutine del_target
    end subroutine parse_keyword_statement

    !> def NAME(parameters): body
    recursive subroutine parse_def(p, ast, stmt, st)
        type(parser_t), intent(inout) :: p
        type(ast_t), intent(inout) :: ast
        integer, intent(out) :: stmt
        type(status_t), intent(inout) :: st
        integer :: body, saved_loops
        stmt = 0
        p%pos = p%pos + 1
        if (peek_kind(p) /= TOK_NAME .or. is_keyword(peek_text(p))) then
            call fail_at(p, st, 'expected the function name after "def"'); return
        end if
        stmt = ast%add(N_DEF, peek_text(p), p%toks(p%pos - 1)%line, p%toks(p%pos - 1)%col)
        p%pos = p%pos + 1
        call expect(p, '(', st)
        if (st%failed()) return
        call parse_parameters(p, ast, stmt, ')', st)
        if (st%failed()) return
        p%pos = p%pos + 1                      ! ')'
        if (is_op(p, '->')) then
            call fail_at(p, st, 'annotations (-> type) are not part of the deck language')
            return
        end if
        p%def_depth = p%def_depth + 1
        saved_loops = p%loop_depth
        p%loop_depth = 0                       ! break/continue do not cross a def
        call parse_block(p, ast, body, st)
        p%loop_depth = saved_loops
        p%def_depth = p%def_depth - 1
        if (st%failed()) return
        call ast%add_kid(stmt, body)
        ast%nodes(stmt)%end_line = ast%nodes(body)%end_line
    end subroutine parse_def

    !> for TARGETS in SEQUENCE: block [else: block]
    recursive subroutine parse_for(p, ast, stmt, st)
        type(parser_t), intent(inout) :: p
        type(ast_t), intent(inout) :: ast
        integer, intent(out) :: stmt
        type(status_t), intent(inout) :: st
        integer :: seq, body, target, orelse, line, col
        stmt = 0
        line = p%toks(p%pos)%line; col = p%toks(p%pos)%col
        p%pos = p%pos + 1
        if (is_name(p, 'in')) then
            call fail_at(p, st, 'expected the loop variable after "for" (for NAME in ' // &
                         'SEQUENCE:)'); return
        end if
        call parse_targets(p, ast, target, st)
        if (st%failed()) return
        call check_target(p, ast, target, st)
        if (st%failed()) return
        if (.not. is_name(p, 'in')) then
            call fail_at(p, st, 'expected "in" after the loop variable, got "' // &
                         peek_text(p) // '"'); return
        end if
        p%pos = p%pos + 1
        call parse_expr_list(p, ast, seq, st)
        if (st%failed()) return
        stmt = ast%add(N_FOR, '', line, col)
        if (ast%nodes(target)%kind == N_NAME) ast%nodes(stmt)%text = ast%nodes(target)%text
        p%loop_depth = p%loop_depth + 1
        call parse_block(p, ast, body, st)
        p%loop_depth = p%loop_depth - 1
        if (st%failed()) return
        call ast%add_kid(stmt, target)
        call ast%add_kid(stmt, seq)
        call ast%add_kid(stmt, body)
        ast%nodes(stmt)%end_line = ast%nodes(body)%end_line
        if (is_name(p, 'else')) then
            p%pos = p%pos + 1
            call parse_block(p, ast, orelse, st)
            if (st%failed()) return
            call ast%add_kid(stmt, orelse)
            ast%nodes(stmt)%end_line = ast%nodes(orelse)%end_line
        end if
    end subroutine parse_for

    !> while CONDITION: block [else: block]
    recursive subroutine parse_while(p, ast, stmt, st)
        type(parser_t), intent(inout) :: p
        type(ast_t), intent(inout) :: ast
        integer, intent(out) :: stmt
        type(status_t), intent(inout) :: st
        integer :: cond, body, orelse
        stmt = ast%add(N_WHILE, 'while', p%toks(p%pos)%line, p%toks(p%pos)%col)
        p%pos = p%pos + 1
        call parse_expr(p, ast, cond, st)
        if (st%failed()) return
        p%loop_depth = p%loop_depth + 1
        call parse_block(p, ast, body, st)
        p%loop_depth = p%loop_depth - 1
        if (st%failed()) return
        call ast%add_kid(stmt, cond)
        call ast%add_kid(stmt, body)
        ast%nodes(stmt)%end_line = ast%nodes(body)%end_line
        if (is_name(p, 'else')) then
            p%pos = p%pos + 1
            call parse_block(p, ast, orelse, st)
            if (st%failed()) return
            call ast%add_kid(stmt, orelse)
            ast%nodes(stmt)%end_line = ast%nodes(orelse)%end_line
        end if
    end subroutine parse_while

    !> import DOTTED [as NAME] [, ...]  |  from DOTTED import * | NAME [as NAME] [, ...]
    !> | ( NAMES )
    subroutine parse_import(p, ast, stmt, st)
        type(parser_t), intent(inout) :: p
        type(ast_t), intent(inout) :: ast
        integer, intent(out) :: stmt
        type(status_t), intent(inout) :: st
        character(len=:), allocatable :: module
        logical :: from, paren
        integer :: line, col, name_node
        from = is_name(p, 'from')
        line = p%toks(p%pos)%line; col = p%toks(p%pos)%col
        stmt = 0
        p%pos = p%pos + 1
        if (.not. from) then
            stmt = ast%add(N_IMPORT, 'import', line, col)
            do
                name_node = ast%add(N_NAME, '', p%toks(p%pos)%line, p%toks(p%pos)%col)
                call dotted_name(module)
                if (st%failed()) return
                ast%nodes(name_node)%text = module
                call alias(name_node)
                if (st%failed()) return
                call ast%add_kid(stmt, name_node)
                if (.not. is_op(p, ',')) exit
                p%pos = p%pos + 1
            end do
            return
        end if
        call dotted_name(module)
        if (st%failed()) return
        stmt = ast%add(N_FROM_IMPORT, module, line, col)
        if (.not. is_name(p, 'import')) then
            call fail_at(p, st, 'expected "import" after "from ' // module // '"'); return
        end if
        p%pos = p%pos + 1
        if (is_op(p, '*')) then
            call ast%add_kid(stmt, ast%add(N_NAME, '*', p%toks(p%pos)%line, p%toks(p%pos)%col))
            p%pos = p%pos + 1
            return
        end if
        paren = is_op(p, '(')
        if (paren) p%pos = p%pos + 1
        do
            if (paren .and. is_op(p, ')')) exit
            if (peek_kind(p) /= TOK_NAME .or. is_keyword(peek_text(p))) then
                call fail_at(p, st, 'expected a name to import, got "' // peek_text(p) // '"')
                return
            end if
            name_node = ast%add(N_NAME, peek_text(p), p%toks(p%pos)%line, p%toks(p%pos)%col)
            p%pos = p%pos + 1
            call alias(name_node)
            if (st%failed()) return
            call ast%add_kid(stmt, name_node)
            if (.not. is_op(p, ',')) exit
            p%pos = p%pos + 1
        end do
        if (paren) call expect(p, ')', st)
    contains
        subroutine dotted_name(name)
            character(len=:), allocatable, intent(out) :: name
            name = ''
            if (is_op(p, '.')) then
                call fail_at(p, st, 'relative imports (from . import x) are not supported ' // &
                             '(name the module)'); return
            end if
            do
                if (peek_kind(p) /= TOK_NAME) then
                    call fail_at(p, st, 'expected a module name, got "' // peek_text(p) // '"')
                    return
                end if
                name = name // peek_text(p)
                p%pos = p%pos + 1
                if (.not. (is_op(p, '.') .and. peek_kind_at(p, p%pos + 1) == TOK_NAME)) exit
                name = name // '.'
                p%pos = p%pos + 1
            end do
        end subroutine dotted_name
        !> `as NAME` after an imported name: the alias, a kid of the name's node.
        subroutine alias(owner)
            integer, intent(in) :: owner
            if (.not. is_name(p, 'as')) return
            p%pos = p%pos + 1
            if (peek_kind(p) /= TOK_NAME .or. is_keyword(peek_text(p))) then
                call fail_at(p, st, 'expected a name after "as", got "' // peek_text(p) // '"')
                return
            end if
            call ast%add_kid(owner, ast%add(N_NAME, peek_text(p), p%toks(p%pos)%line, &
                                            p%toks(p%pos)%col))
            p%pos = p%pos + 1
        end subroutine alias
    end subroutine parse_import

    !> if cond: block [elif cond: block]* [else: block]
    recursive subroutine parse_if(p, ast, stmt, st)
        type(parser_t), intent(inout) :: p
        type(ast_t), intent(inout) :: ast
        integer, intent(out) :: stmt
        type(status_t), intent(inout) :: st
        integer :: cond, body, orelse, inner
        stmt = ast%add(N_IF, 'if', p%toks(p%pos)%line, p%toks(p%pos)%col)
        p%pos = p%pos + 1
        call parse_expr(p, ast, cond, st)
        if (st%failed()) return
        call parse_block(p, ast, body, st)
        if (st%failed()) return
        call ast%add_kid(stmt, cond)
        call ast%add_kid(stmt, body)
        ast%nodes(stmt)%end_line = ast%nodes(body)%end_line
        if (is_name(p, 'elif')) then
            call enter(p, st)
            if (st%failed()) return
            orelse = ast%add(N_BLOCK, '', p%toks(p%pos)%line, p%toks(p%pos)%col)
            call parse_if(p, ast, inner, st)
            call leave(p)
            if (st%failed()) return
            call ast%add_kid(orelse, inner)
            ast%nodes(orelse)%end_line = ast%nodes(inner)%end_line
            call ast%add_kid(stmt, orelse)
            ast%nodes(stmt)%end_line = ast%nodes(orelse)%end_line
        else if (is_name(p, 'else')) then
            p%pos = p%pos + 1
            call parse_block(p, ast, orelse, st)
            if (st%failed()) return
            call ast%add_kid(stmt, orelse)
            ast%nodes(stmt)%end_line = ast%nodes(orelse)%end_line
        end if
    end subroutine parse_if

    !> ':' then simple statements on the same line, or NEWLINE INDENT statements DEDENT.
    recursive subroutine parse_block(p, ast, block, st)
        type(parser_t), intent(inout) :: p
        type(ast_t), intent(inout) :: ast
        integer, intent(out) :: block
        type(status_t), intent(inout) :: st
        block = 0
        call expect(p, ':', st)
        if (st%failed()) return
        block = ast%add(N_BLOCK, '', p%toks(p%pos)%line, p%toks(p%pos)%col)
        p%block_depth = p%block_depth + 1
        call parse_block_body(p, ast, block, st)
        p%block_depth = p%block_depth - 1
    end subroutine parse_block

    !> The statements of a block (after its ':').
    recursive subroutine parse_block_body(p, ast, block, st)
        type(parser_t), intent(inout) :: p
        type(ast_t), intent(inout) :: ast
        integer, intent(in) :: block
        type(status_t), intent(inout) :: st
        integer :: j
        if (peek_kind(p) /= TOK_NEWLINE) then
            call parse_statement_line(p, ast, block, st)
            ast%nodes(block)%end_line = p%toks(max(1, p%pos - 1))%line
            return
        end if
        p%pos = p%pos + 1
        if (peek_kind(p) /= TOK_INDENT) then
            call fail_at(p, st, 'expected an indented block after ":"'); return
        end if
        p%pos = p%pos + 1
        do
            call skip_newlines(p)
            if (peek_kind(p) == TOK_DEDENT .or. peek_kind(p) == TOK_EOF) then
                j = p%pos - 1                  ! the line of the last token before DEDENTs
                do while (j > 1 .and. p%toks(j)%kind == TOK_DEDENT)
                    j = j - 1
                end do
                ast%nodes(block)%end_line = p%toks(max(1, j))%line
                if (peek_kind(p) == TOK_DEDENT) p%pos = p%pos + 1
                exit
            end if
            call parse_statement_line(p, ast, block, st)
            if (st%failed()) return
        end do
    end subroutine parse_block_body

    !> Python keywords that start constructs outside the language.
    subroutine refuse_keywords(p, st)
        type(parser_t), intent(inout) :: p
        type(status_t), intent(inout) :: st
        if (peek_kind(p) /= TOK_NAME) return
        select case (peek_text(p))
        case ('import', 'from')
            call fail_at(p, st, '"' // peek_text(p) // '" starts a statement of its own ' // &
                '(import NAME, from NAME import ...)')
        case ('for', 'while')
            call fail_at(p, st, 'unexpected keyword "' // peek_text(p) // '" (a loop is a ' // &
                'statement of its own)')
        case ('class')
            call fail_at(p, st, '"class" definitions are not part of the deck language')
        case ('try', 'except', 'finally')
            call fail_at(p, st, '"' // peek_text(p) // '" (exceptions) is not part of the ' // &
                'deck language: an error stops the run with its location')
        case ('with', 'global', 'nonlocal', 'yield', 'async', 'await')
            call fail_at(p, st, '"' // peek_text(p) // '" is not part of the deck language')
        case ('else', 'elif')
            call fail_at(p, st, '"' // peek_text(p) // '" without a matching "if", "for" ' // &
                'or "while"')
        end select
    end subroutine refuse_keywords

end module deck_parser
