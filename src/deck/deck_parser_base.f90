!> The parser's state and the token helpers the statement parser (deck_parser) and the
!> expression parser (deck_parser_expr) share: looking at the next tokens, expecting one,
!> failing at one, and the nesting bound MAX_DEPTH that keeps every input from overflowing
!> the stack.
module deck_parser_base
    use status, only: status_t, set_error, STATUS_DECK_ERROR
    use deck_lexer, only: token_t, TOK_EOF, TOK_NEWLINE, TOK_INDENT, TOK_DEDENT, TOK_OP, TOK_NAME
    implicit none
    private

    !> Deepest expression/statement nesting accepted, counting operator chains too (a+b+c
    !> is a tree of depth 3): far below what gfortran's stack holds for the evaluators.
    integer, parameter, public :: MAX_DEPTH = 500

    !> One parse: the tokens, the read position, the nesting depth and the constructs the
    !> statement being read sits in (def, loops, blocks).
    type, public :: parser_t
        type(token_t), allocatable :: toks(:)
        integer :: pos = 1
        integer :: depth = 0
        integer :: def_depth = 0
        integer :: loop_depth = 0     !< loops around the statement (break/continue)
        integer :: block_depth = 0    !< indented blocks around the statement
        character(len=:), allocatable :: file
    end type parser_t

    public :: enter, leave, skip_newlines, expect, fail_at, peek_kind, peek_kind_at, &
        peek_text, is_op, is_op_at, is_name, is_name_at, is_keyword

contains

    !> One level deeper; an error past MAX_DEPTH.
    subroutine enter(p, st)
        type(parser_t), intent(inout) :: p
        type(status_t), intent(inout) :: st
        p%depth = p%depth + 1
        if (p%depth > MAX_DEPTH) call fail_at(p, st, 'expression nested or chained deeper ' &
                                              // 'than 500 levels (simplify it)')
    end subroutine enter

    subroutine leave(p)
        type(parser_t), intent(inout) :: p
        p%depth = p%depth - 1
    end subroutine leave

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

    !> A located error at the next token (the first error is kept).
    subroutine fail_at(p, st, message)
        type(parser_t), intent(in) :: p
        type(status_t), intent(inout) :: st
        character(len=*), intent(in) :: message
        integer :: k
        if (st%failed()) return
        k = min(p%pos, size(p%toks))
        call set_error(st, STATUS_DECK_ERROR, message, file=p%file, &
                       line=p%toks(k)%line, column=p%toks(k)%col)
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

    !> The next token as named in messages.
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
        case (TOK_DEDENT)
            t = 'end of block'
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
        is_name = is_name_at(p, p%pos, word)
    end function is_name

    logical function is_name_at(p, k, word)
        type(parser_t), intent(in) :: p
        integer, intent(in) :: k
        character(len=*), intent(in) :: word
        integer :: j
        j = min(k, size(p%toks))
        is_name_at = p%toks(j)%kind == TOK_NAME
        if (is_name_at) is_name_at = p%toks(j)%text == word
    end function is_name_at

    !> True for Python's reserved words (they cannot be names).
    pure logical function is_keyword(word)
        character(len=*), intent(in) :: word
        select case (word)
        case ('False', 'None', 'True', 'and', 'as', 'assert', 'async', 'await', 'break', &
              'class', 'continue', 'def', 'del', 'elif', 'else', 'except', 'finally', 'for', &
              'from', 'global', 'if', 'import', 'in', 'is', 'lambda', 'nonlocal', 'not', 'or', &
              'pass', 'raise', 'return', 'try', 'while', 'with', 'yield')
            is_keyword = .true.
        case default
            is_keyword = .false.
        end select
    end function is_keyword

end module deck_parser_base
