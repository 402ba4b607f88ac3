!> Recursive-descent parser of the deck language (doc/deck-language.md) to a deck_ast tree.
!> Constructs outside the subset are refused with a message naming them. Recursion is bounded
!> by MAX_DEPTH so no input can overflow the stack.
module deck_parser
    use kinds, only: i4
    use status, only: status_t, set_error, STATUS_DECK_ERROR
    use deck_lexer, only: token_t, tokenize, TOK_EOF, TOK_NAME, TOK_INT, TOK_REAL, TOK_STRING, &
        TOK_OP, TOK_NEWLINE, TOK_INDENT, TOK_DEDENT
    use deck_ast
    implicit none
    private

    !> Deepest expression/statement nesting accepted, counting operator chains too (a+b+c
    !> is a tree of depth 3): far below what gfortran's stack holds for the evaluators.
    integer, parameter, public :: MAX_DEPTH = 500

    type :: parser_t
        type(token_t), allocatable :: toks(:)
        integer :: pos = 1
        integer :: depth = 0
        integer :: def_depth = 0
        integer :: loop_depth = 0     !< for loops around the statement (break/continue)
        integer :: block_depth = 0    !< indented blocks around the statement (imports)
        character(len=:), allocatable :: file
    end type parser_t

    public :: parse_deck, parse_expression

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
        if (is_name(p, 'def') .or. is_name(p, 'if') .or. is_name(p, 'for')) then
            call enter(p, st)
            if (st%failed()) return
            if (is_name(p, 'def')) then
                call parse_def(p, ast, stmt, st)
            else if (is_name(p, 'for')) then
                call parse_for(p, ast, stmt, st)
            else
                call parse_if(p, ast, stmt, st)
            end if
            p%depth = p%depth - 1
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

    !> Assignment, expression statement, return, pass.
    recursive subroutine parse_simple(p, ast, stmt, st)
        type(parser_t), intent(inout) :: p
        type(ast_t), intent(inout) :: ast
        integer, intent(out) :: stmt
        type(status_t), intent(inout) :: st
        integer :: e, value, line, col, op_line, op_col
        character(len=:), allocatable :: op
        stmt = 0
        line = p%toks(p%pos)%line; col = p%toks(p%pos)%col
        if (is_name(p, 'import') .or. is_name(p, 'from')) then
            call parse_import(p, ast, stmt, st)
            if (st%ok()) ast%nodes(stmt)%end_line = p%toks(max(1, p%pos - 1))%line
            return
        end if
        if (is_name(p, 'break') .or. is_name(p, 'continue')) then
            if (p%loop_depth == 0) then
                call fail_at(p, st, '"' // peek_text(p) // '" outside a for loop'); return
            end if
            stmt = ast%add(merge(N_BREAK, N_CONTINUE, is_name(p, 'break')), peek_text(p), &
                           line, col)
            p%pos = p%pos + 1
            return
        end if
        call refuse_keywords(p, st)
        if (st%failed()) return
        if (is_name(p, 'return')) then
            if (p%def_depth == 0) then
                call fail_at(p, st, '"return" outside a def'); return
            end if
            p%pos = p%pos + 1
            stmt = ast%add(N_RETURN, 'return', line, col)
            call parse_expr_list(p, ast, e, st)
            if (st%failed()) return
            call ast%add_kid(stmt, e)
            return
        end if
        if (is_name(p, 'pass')) then
            p%pos = p%pos + 1
            stmt = ast%add(N_PASS, 'pass', line, col)
            return
        end if
        call parse_expr_list(p, ast, e, st)
        if (st%failed()) return
        if (is_op(p, '=') .or. is_op(p, '+=') .or. is_op(p, '-=') .or. is_op(p, '*=') &
            .or. is_op(p, '/=')) then
            op = peek_text(p)
            op_line = p%toks(p%pos)%line; op_col = p%toks(p%pos)%col
            if (ast%nodes(e)%kind /= N_NAME .or. index(ast%nodes(e)%text, '.') > 0) then
                call set_error(st, STATUS_DECK_ERROR, 'only a plain name can be assigned ' // &
                    '(e.g. MAIL = LIRE_MAILLAGE(...)); is "=" meant to be "=="?', &
                    file=p%file, line=ast%nodes(e)%line, column=ast%nodes(e)%col)
                return
            end if
            p%pos = p%pos + 1
            call parse_expr_list(p, ast, value, st)
            if (st%failed()) return
            if (op /= '=') then
                ! x += v is x = x + v
                stmt = ast%add(N_BINOP, op(1:1), op_line, op_col)
                call ast%add_kid(stmt, ast%add(N_NAME, ast%nodes(e)%text, line, col))
                call ast%add_kid(stmt, value)
                value = stmt
            end if
            stmt = ast%add(N_ASSIGN, ast%nodes(e)%text, line, col)
            call ast%add_kid(stmt, value)
        else
            stmt = ast%add(N_EXPR, '', line, col)
            call ast%add_kid(stmt, e)
        end if
        ast%nodes(stmt)%end_line = p%toks(max(1, p%pos - 1))%line
    end subroutine parse_simple

    !> def NAME(p1, p2, ...): body
    recursive subroutine parse_def(p, ast, stmt, st)
        type(parser_t), intent(inout) :: p
        type(ast_t), intent(inout) :: ast
        integer, intent(out) :: stmt
        type(status_t), intent(inout) :: st
        integer :: body, saved_loops
        stmt = 0
        p%pos = p%pos + 1
        if (peek_kind(p) /= TOK_NAME) then
            call fail_at(p, st, 'expected the function name after "def"'); return
        end if
        stmt = ast%add(N_DEF, peek_text(p), p%toks(p%pos - 1)%line, p%toks(p%pos - 1)%col)
        p%pos = p%pos + 1
        call expect(p, '(', st)
        if (st%failed()) return
        do while (.not. is_op(p, ')'))
            if (is_op(p, '*') .or. is_op(p, '**')) then
                call fail_at(p, st, '*args and **kwargs are not supported in the deck ' // &
                             'language (name each parameter)'); return
            end if
            if (peek_kind(p) /= TOK_NAME) then
                call fail_at(p, st, 'expected a parameter name'); return
            end if
            if (is_op_at(p, p%pos + 1, '=')) then
                call fail_at(p, st, 'default parameter values are not supported'); return
            end if
            call ast%add_kid(stmt, ast%add(N_NAME, peek_text(p), p%toks(p%pos)%line, &
                                           p%toks(p%pos)%col))
            p%pos = p%pos + 1
            if (is_op(p, ',')) then
                p%pos = p%pos + 1
            else if (.not. is_op(p, ')')) then
                call fail_at(p, st, 'expected "," or ")" in the parameter list'); return
            end if
        end do
        p%pos = p%pos + 1
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

    !> for NAME in SEQUENCE: block   (one loop variable; no else clause)
    recursive subroutine parse_for(p, ast, stmt, st)
        type(parser_t), intent(inout) :: p
        type(ast_t), intent(inout) :: ast
        integer, intent(out) :: stmt
        type(status_t), intent(inout) :: st
        integer :: seq, body
        stmt = 0
        p%pos = p%pos + 1
        if (peek_kind(p) /= TOK_NAME) then
            call fail_at(p, st, 'expected the loop variable after "for" (for NAME in ' // &
                         'SEQUENCE:)'); return
        end if
        select case (peek_text(p))
        case ('in', 'for', 'if', 'def', 'and', 'or', 'not', 'None', 'True', 'False')
            call fail_at(p, st, 'expected the loop variable after "for" (for NAME in ' // &
                         'SEQUENCE:)'); return
        end select
        stmt = ast%add(N_FOR, peek_text(p), p%toks(p%pos - 1)%line, p%toks(p%pos - 1)%col)
        p%pos = p%pos + 1
        if (is_op(p, ',')) then
            call fail_at(p, st, 'several loop variables are not supported (one NAME: ' // &
                         'for x in SEQUENCE:, then x[0], x[1])'); return
        end if
        if (.not. is_name(p, 'in')) then
            call fail_at(p, st, 'expected "in" after the loop variable, got "' // &
                         peek_text(p) // '"'); return
        end if
        p%pos = p%pos + 1
        call parse_expr_list(p, ast, seq, st)
        if (st%failed()) return
        p%loop_depth = p%loop_depth + 1
        call parse_block(p, ast, body, st)
        p%loop_depth = p%loop_depth - 1
        if (st%failed()) return
        call ast%add_kid(stmt, seq)
        call ast%add_kid(stmt, body)
        ast%nodes(stmt)%end_line = ast%nodes(body)%end_line
        if (is_name(p, 'else')) then
            call fail_at(p, st, '"else" after a for loop is not supported (use a flag ' // &
                         'set before break)'); return
        end if
    end subroutine parse_for

    !> import DOTTED [, DOTTED]*  |  from DOTTED import * | NAME [, NAME]* | ( NAMES )
    !> Only at the top level of a file (imports bind the file's names).
    subroutine parse_import(p, ast, stmt, st)
        type(parser_t), intent(inout) :: p
        type(ast_t), intent(inout) :: ast
        integer, intent(out) :: stmt
        type(status_t), intent(inout) :: st
        character(len=:), allocatable :: module
        logical :: from, paren
        integer :: line, col
        from = is_name(p, 'from')
        line = p%toks(p%pos)%line; col = p%toks(p%pos)%col
        stmt = 0
        if (p%block_depth > 0) then
            call fail_at(p, st, 'imports are only supported at the top level of a file ' // &
                         '(not inside def, if or for)'); return
        end if
        p%pos = p%pos + 1
        if (.not. from) then
            stmt = ast%add(N_IMPORT, 'import', line, col)
            do
                call dotted_name(module)
                if (st%failed()) return
                call ast%add_kid(stmt, ast%add(N_NAME, module, line, col))
                if (.not. is_op(p, ',')) exit
                p%pos = p%pos + 1
            end do
            call refuse_as()
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
            if (peek_kind(p) /= TOK_NAME) then
                call fail_at(p, st, 'expected a name to import, got "' // peek_text(p) // '"')
                return
            end if
            call ast%add_kid(stmt, ast%add(N_NAME, peek_text(p), p%toks(p%pos)%line, &
                                           p%toks(p%pos)%col))
            p%pos = p%pos + 1
            call refuse_as()
            if (st%failed()) return
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
        subroutine refuse_as()
            if (is_name(p, 'as')) call fail_at(p, st, '"as" (renaming an import) is not ' // &
                'supported (import the name as it is)')
        end subroutine refuse_as
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
            p%depth = p%depth - 1
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

    !> Python keywords that start constructs outside the subset.
    subroutine refuse_keywords(p, st)
        type(parser_t), intent(inout) :: p
        type(status_t), intent(inout) :: st
        if (peek_kind(p) /= TOK_NAME) return
        select case (peek_text(p))
        case ('import', 'from')
            call fail_at(p, st, '"' // peek_text(p) // '" starts a statement of its own ' // &
                '(from NAME import ..., import math)')
        case ('for', 'break', 'continue')
            call fail_at(p, st, 'unexpected keyword "' // peek_text(p) // '" (a for loop ' // &
                'is a statement of its own: for NAME in SEQUENCE:)')
        case ('while')
            call fail_at(p, st, '"while" loops are not part of the deck language (use ' // &
                'for NAME in range(N): with break)')
        case ('class')
            call fail_at(p, st, '"class" definitions are not part of the deck language')
        case ('lambda')
            call fail_at(p, st, '"lambda" is not part of the deck language (use def or FORMULE)')
        case ('with', 'try', 'except', 'finally', 'raise', 'global', 'nonlocal', 'del', &
              'assert', 'yield', 'async', 'await', 'print', 'exec', 'eval')
            call fail_at(p, st, '"' // peek_text(p) // '" is not part of the deck language')
        case ('else', 'elif')
            call fail_at(p, st, '"' // peek_text(p) // '" without a matching "if"')
        end select
    end subroutine refuse_keywords

    ! ---- expressions ------------------------------------------------------------------------

    !> expr [, expr]* : a bare tuple (e.g. `return a, b` or `x = 1, 2`).
    recursive subroutine parse_expr_list(p, ast, e, st)
        type(parser_t), intent(inout) :: p
        type(ast_t), intent(inout) :: ast
        integer, intent(out) :: e
        type(status_t), intent(inout) :: st
        integer :: first, item
        call parse_expr(p, ast, first, st)
        e = first
        if (st%failed() .or. .not. is_op(p, ',')) return
        e = ast%add(N_TUPLE, '', ast%nodes(first)%line, ast%nodes(first)%col)
        call ast%add_kid(e, first)
        do while (is_op(p, ','))
            p%pos = p%pos + 1
            if (any(peek_kind(p) == [TOK_NEWLINE, TOK_EOF]) .or. is_op(p, '=') .or. &
                is_op(p, ';')) exit
            call parse_expr(p, ast, item, st)
            if (st%failed()) return
            call ast%add_kid(e, item)
        end do
    end subroutine parse_expr_list

    !> expr := or_test ['if' or_test 'else' expr]
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
            call fail_at(p, st, '"lambda" is not part of the deck language (use def or FORMULE)')
            return
        end if
        call parse_bool(p, ast, N_OR, e, st)
        if (st%failed()) return
        if (is_name(p, 'if')) then
            node = ast%add(N_IFEXP, 'if', p%toks(p%pos)%line, p%toks(p%pos)%col)
            p%pos = p%pos + 1
            call parse_bool(p, ast, N_OR, cond, st)
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
        p%depth = p%depth - 1
    end subroutine parse_expr

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
            p%depth = p%depth - 1
        else
            call parse_compare(p, ast, e, st)
        end if
    end subroutine parse_not

    recursive subroutine parse_compare(p, ast, e, st)
        type(parser_t), intent(inout) :: p
        type(ast_t), intent(inout) :: ast
        integer, intent(out) :: e
        type(status_t), intent(inout) :: st
        integer :: item, node
        character(len=:), allocatable :: ops
        call parse_binary(p, ast, 1, e, st)
        if (st%failed() .or. .not. is_compare(p)) return
        node = ast%add(N_COMPARE, '', ast%nodes(e)%line, ast%nodes(e)%col)
        call ast%add_kid(node, e)
        ops = ''
        do while (is_compare(p))
            if (is_name(p, 'in') .or. is_name(p, 'is')) then
                call fail_at(p, st, '"' // peek_text(p) // '" is not supported (compare with ' &
                             // '== or !=)'); return
            end if
            ops = ops // peek_text(p) // ' '
            p%pos = p%pos + 1
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
            .or. is_name(p, 'is')
    end function is_compare

    !> Binary operators by level: 1 = + -, 2 = * / // %; both left-associative.
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
        if (is_op(p, '@') .or. is_op(p, '&') .or. is_op(p, '|') .or. is_op(p, '^')) then
            call fail_at(p, st, 'operator "' // peek_text(p) // '" is not supported')
        end if
    end subroutine parse_binary

    !> factor := ('+'|'-') factor | power   (so -x**2 is -(x**2), as in Python)
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
            p%depth = p%depth - 1
        else if (is_op(p, '~')) then
            call fail_at(p, st, 'operator "~" is not supported'); e = 0
        else
            call parse_power(p, ast, e, st)
        end if
    end subroutine parse_unary

    !> power := primary ['**' factor]  (right-associative)
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
        p%depth = p%depth - 1
        call ast%add_kid(node, e)
        call ast%add_kid(node, exponent)
        e = node
    end subroutine parse_power

    !> atom followed by calls `( ... )`; `math.NAME` becomes the name 'math.NAME'.
    recursive subroutine parse_primary(p, ast, e, st)
        type(parser_t), intent(inout) :: p
        type(ast_t), intent(inout) :: ast
        integer, intent(out) :: e
        type(status_t), intent(inout) :: st
        integer :: call_node, chain
        call parse_atom(p, ast, e, st)
        if (st%failed()) return
        chain = 0
        do
            if (is_op(p, '.')) then
                if (ast%nodes(e)%kind == N_NAME .and. ast%nodes(e)%text == 'math' .and. &
                    peek_kind_at(p, p%pos + 1) == TOK_NAME) then
                    ast%nodes(e)%text = 'math.' // p%toks(p%pos + 1)%text
                    p%pos = p%pos + 2
                    cycle
                end if
                if (peek_kind_at(p, p%pos + 1) /= TOK_NAME) then
                    p%pos = p%pos + 1
                    call fail_at(p, st, 'expected an attribute name after "."'); return
                end if
                call enter(p, st)                ! a.b.c... chains as deep as it is long
                if (st%failed()) return
                chain = chain + 1
                call_node = ast%add(N_ATTR, p%toks(p%pos + 1)%text, p%toks(p%pos + 1)%line, &
                                    p%toks(p%pos + 1)%col)
                call ast%add_kid(call_node, e)
                e = call_node
                p%pos = p%pos + 2
                cycle
            end if
            if (.not. (is_op(p, '(') .or. is_op(p, '['))) exit
            call enter(p, st)                    ! f()()... and x[0][0]... chain as deep
            if (st%failed()) return
            chain = chain + 1
            if (is_op(p, '(')) then
                call_node = ast%add(N_CALL, '', p%toks(p%pos)%line, p%toks(p%pos)%col)
                call ast%add_kid(call_node, e)
                call parse_arguments(p, ast, call_node, st)
                if (st%failed()) return
                e = call_node
            else
                call parse_subscript(p, ast, e, st)
                if (st%failed()) return
            end if
        end do
        p%depth = p%depth - chain
    end subroutine parse_primary

    !> e[index] or a slice e[start:stop:step] (each part optional).
    recursive subroutine parse_subscript(p, ast, e, st)
        type(parser_t), intent(inout) :: p
        type(ast_t), intent(inout) :: ast
        integer, intent(inout) :: e
        type(status_t), intent(inout) :: st
        integer :: node, part(3), k, line, col
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
                node = ast%add(N_TUPLE, '', ast%nodes(part(1))%line, ast%nodes(part(1))%col)
                call ast%add_kid(node, part(1))
                do while (is_op(p, ','))
                    p%pos = p%pos + 1
                    if (is_op(p, ']')) exit
                    call parse_expr(p, ast, k, st)
                    if (st%failed()) return
                    call ast%add_kid(node, k)
                end do
                part(1) = node
                if (.not. is_op(p, ']')) then
                    call fail_at(p, st, 'expected "]" after the index, got "' // &
                                 peek_text(p) // '" (a slice has no ",")'); return
                end if
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
                             peek_text(p) // '" (one index per subscript: x[i][j])'); return
            end if
        end if
        p%pos = p%pos + 1                        ! the first ':'
        if (.not. (is_op(p, ':') .or. is_op(p, ']'))) then
            call parse_expr(p, ast, part(2), st)
            if (st%failed()) return
            parts(2:2) = '1'
        end if
        if (is_op(p, ':')) then
            p%pos = p%pos + 1
            if (.not. is_op(p, ']')) then
                call parse_expr(p, ast, part(3), st)
                if (st%failed()) return
                parts(3:3) = '1'
            end if
        end if
        call expect(p, ']', st)
        if (st%failed()) return
        node = ast%add(N_SLICE, parts, line, col)
        call ast%add_kid(node, e)
        do k = 1, 3
            if (parts(k:k) == '1') call ast%add_kid(node, part(k))
        end do
        e = node
    end subroutine parse_subscript

    !> ( [arg | NAME=expr] , ... ) — positional arguments must come first.
    recursive subroutine parse_arguments(p, ast, call_node, st)
        type(parser_t), intent(inout) :: p
        type(ast_t), intent(inout) :: ast
        integer, intent(in) :: call_node
        type(status_t), intent(inout) :: st
        integer :: arg, kw
        logical :: seen_keyword
        p%pos = p%pos + 1
        seen_keyword = .false.
        do while (.not. is_op(p, ')'))
            if (is_op(p, '*') .or. is_op(p, '**')) then
                call fail_at(p, st, '*args and **kwargs are not supported in the deck ' // &
                             'language (name each keyword)'); return
            end if
            if (peek_kind(p) == TOK_NAME .and. is_op_at(p, p%pos + 1, '=')) then
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
                    call fail_at(p, st, 'comprehensions/generators ("for" inside brackets) ' &
                                 // 'are not part of the deck language'); return
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

    recursive subroutine parse_atom(p, ast, e, st)
        type(parser_t), intent(inout) :: p
        type(ast_t), intent(inout) :: ast
        integer, intent(out) :: e
        type(status_t), intent(inout) :: st
        integer :: line, col
        character(len=:), allocatable :: s
        e = 0
        line = p%toks(p%pos)%line; col = p%toks(p%pos)%col
        select case (peek_kind(p))
        case (TOK_INT)
            e = ast%add(N_INT, peek_text(p), line, col); p%pos = p%pos + 1
        case (TOK_REAL)
            e = ast%add(N_REAL, peek_text(p), line, col); p%pos = p%pos + 1
        case (TOK_STRING)
            s = ''
            do while (peek_kind(p) == TOK_STRING)    ! 'a' 'b' is 'ab'
                s = s // p%toks(p%pos)%text
                p%pos = p%pos + 1
            end do
            e = ast%add(N_STR, s, line, col)
        case (TOK_NAME)
            call refuse_keywords(p, st)
            if (st%failed()) return
            select case (peek_text(p))
            case ('def', 'if', 'return', 'pass', 'and', 'or', 'else', 'elif', 'in', 'is')
                call fail_at(p, st, 'unexpected keyword "' // peek_text(p) // &
                             '" inside an expression'); return
            end select
            e = ast%add(N_NAME, peek_text(p), line, col); p%pos = p%pos + 1
        case (TOK_OP)
            select case (peek_text(p))
            case ('(')
                call parse_sequence(p, ast, ')', N_TUPLE, e, st)
            case ('[')
                call parse_sequence(p, ast, ']', N_LIST, e, st)
            case ('{')
                call fail_at(p, st, 'dictionaries and sets { } are not part of the deck ' // &
                             'language (use _F(KEY=value) for keyword groups)')
            case default
                call fail_at(p, st, 'unexpected "' // peek_text(p) // '" (expected a value)')
            end select
        case (TOK_EOF)
            call fail_at(p, st, 'unexpected end of file (an expression is incomplete)')
        case default
            call fail_at(p, st, 'unexpected end of line (an expression is incomplete)')
        end select
    end subroutine parse_atom

    !> '(' ... ')' or '[' ... ']': a parenthesized expression, a tuple or a list.
    recursive subroutine parse_sequence(p, ast, closing, kind, e, st)
        type(parser_t), intent(inout) :: p
        type(ast_t), intent(inout) :: ast
        character(len=1), intent(in) :: closing
        integer, intent(in) :: kind
        integer, intent(out) :: e
        type(status_t), intent(inout) :: st
        integer :: item, node, count
        logical :: trailing_comma
        node = ast%add(kind, '', p%toks(p%pos)%line, p%toks(p%pos)%col)
        e = node
        p%pos = p%pos + 1
        count = 0; trailing_comma = .false.
        do while (.not. is_op(p, closing))
            call parse_expr(p, ast, item, st)
            if (st%failed()) return
            if (is_name(p, 'for')) then
                call fail_at(p, st, 'comprehensions ("for" inside brackets) are not part ' // &
                             'of the deck language (write the values out)'); return
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
        if (kind == N_TUPLE .and. count == 1 .and. .not. trailing_comma) then
            e = item                              ! (x) is x, (x,) is a 1-tuple
        end if
    end subroutine parse_sequence

    ! ---- helpers ----------------------------------------------------------------------------

    subroutine enter(p, st)
        type(parser_t), intent(inout) :: p
        type(status_t), intent(inout) :: st
        p%depth = p%depth + 1
        if (p%depth > MAX_DEPTH) call fail_at(p, st, 'expression nested or chained deeper ' &
                                              // 'than 500 levels (simplify it)')
    end subroutine enter

    subroutine skip_newlines(p)
        type(parser_t), intent(inout) :: p
        do while (peek_kind(p) == TOK_NEWLINE)
            p%pos = p%pos + 1
        end do
    end subroutine skip_newlines

    subroutine expect(p, op, st)
        type(parser_t), intent(inout) :: p
        character(len=*), intent(in) :: op
        type(status_t), intent(inout) :: st
        if (is_op(p, op)) then
            p%pos = p%pos + 1
        else
            call fail_at(p, st, 'expected "' // op // '", got "' // peek_text(p) // '"')
        end if
    end subroutine expect

    subroutine fail_at(p, st, message)
        type(parser_t), intent(in) :: p
        type(status_t), intent(inout) :: st
        character(len=*), intent(in) :: message
        if (st%failed()) return
        call set_error(st, STATUS_DECK_ERROR, message, file=p%file, &
                       line=p%toks(p%pos)%line, column=p%toks(p%pos)%col)
    end subroutine fail_at

    integer function peek_kind(p)
        type(parser_t), intent(in) :: p
        peek_kind = p%toks(min(p%pos, size(p%toks)))%kind
    end function peek_kind

    integer function peek_kind_at(p, k)
        type(parser_t), intent(in) :: p
        integer, intent(in) :: k
        peek_kind_at = p%toks(min(k, size(p%toks)))%kind
    end function peek_kind_at

    function peek_text(p) result(t)
        type(parser_t), intent(in) :: p
        character(len=:), allocatable :: t
        select case (peek_kind(p))
        case (TOK_NEWLINE)
            t = 'end of line'
        case (TOK_EOF)
            t = 'end of file'
        case (TOK_INDENT)
            t = 'indentation'
        case default
            t = p%toks(min(p%pos, size(p%toks)))%text
        end select
    end function peek_text

    logical function is_op(p, op)
        type(parser_t), intent(in) :: p
        character(len=*), intent(in) :: op
        is_op = is_op_at(p, p%pos, op)
    end function is_op

    logical function is_op_at(p, k, op)
        type(parser_t), intent(in) :: p
        integer, intent(in) :: k
        character(len=*), intent(in) :: op
        integer :: j
        j = min(k, size(p%toks))
        is_op_at = p%toks(j)%kind == TOK_OP
        if (is_op_at) is_op_at = p%toks(j)%text == op
    end function is_op_at

    logical function is_name(p, word)
        type(parser_t), intent(in) :: p
        character(len=*), intent(in) :: word
        is_name = peek_kind(p) == TOK_NAME
        if (is_name) is_name = p%toks(p%pos)%text == word
    end function is_name

end module deck_parser
