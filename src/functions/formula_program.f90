!> Compiled FORMULE expressions: flat bytecode over a real value stack, and the loop that
!> runs it. Compiled once by formula_compiler, evaluated many times (the load layer calls a
!> formula at every Gauss point of every step). Unit 1 is the VALE expression; further
!> units are `def` functions it calls. Every arithmetic operation is checked before it is
!> done (deck_math), so a bad value gives a located error, never an FP trap.
module formula_program
    use kinds, only: dp
    use strings, only: string_t, to_text
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use deck_math, only: checked_binary, checked_pow, checked_call, math_message, MATH_OK, &
        same_real, B_MIN, B_MAX, builtin_name
    use function_concept, only: function_concept_t, param_binding_t
    implicit none
    private

    !> Opcodes; operands follow in the code array.
    integer, parameter, public :: OP_CONST = 1, OP_PARAM = 2, OP_LOAD = 3, OP_STORE = 4, &
        OP_NEG = 5, OP_ADD = 6, OP_SUB = 7, OP_MUL = 8, OP_DIV = 9, OP_FLOORDIV = 10, &
        OP_MOD = 11, OP_POW = 12, OP_LT = 13, OP_LE = 14, OP_GT = 15, OP_GE = 16, OP_EQ = 17, &
        OP_NE = 18, OP_NOT = 19, OP_JUMP = 20, OP_JUMP_IF_FALSE = 21, &
        OP_JUMP_IF_FALSE_OR_POP = 22, OP_JUMP_IF_TRUE_OR_POP = 23, OP_BUILTIN = 24, &
        OP_CALL_DEF = 25, OP_CALL_FUNC = 26, OP_RETURN = 27, OP_POP = 28, OP_NO_RETURN = 29, &
        OP_SQUARE = 30
    !> Operand count of each opcode.
    integer, parameter, public :: OP_OPERANDS(30) = [1, 1, 1, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, &
        0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 0, 0, 0, 0]

    !> Symbols of OP_ADD .. OP_MOD for checked_binary.
    character(len=2), parameter :: SYMBOLS(6) = ['+ ', '- ', '* ', '/ ', '//', '% ']

    !> Sums of operands below this size cannot overflow.
    real(dp), parameter :: HALF_HUGE = 0.5_dp * huge(1.0_dp)

    !> Value stack size, locals size and call depth of the evaluator (checked at compile time).
    integer, parameter, public :: MAX_STACK = 256, MAX_LOCALS = 512, MAX_FRAMES = 32

    !> One compiled body. line/col give the deck position of the instruction at each code
    !> index (for runtime errors).
    type, public :: code_unit_t
        character(len=:), allocatable :: name
        character(len=:), allocatable :: file     !< a def's file, if not the program's
        integer, allocatable :: code(:), line(:), col(:)
        integer :: ncode = 0
        real(dp), allocatable :: consts(:)
        integer :: nconst = 0
        integer :: nparams = 0, nlocals = 0
    contains
        procedure :: emit => unit_emit
        procedure :: constant => unit_constant
    end type code_unit_t

    !> A function concept called from the formula, with the binding of its own parameters.
    type, public :: callee_t
        class(function_concept_t), allocatable :: f
        type(param_binding_t) :: binding
        integer :: nargs = 0
    end type callee_t

    type, public :: program_t
        type(code_unit_t), allocatable :: units(:)
        integer :: nunit = 0
        type(callee_t), allocatable :: callees(:)
        integer :: ncallee = 0
        character(len=:), allocatable :: file          !< deck file, for messages
    end type program_t

    public :: run_program

contains

    !> Appends an instruction (opcode and operands) at deck position (line, col).
    subroutine unit_emit(self, op, line, col, a, b)
        class(code_unit_t), intent(inout) :: self
        integer, intent(in) :: op, line, col
        integer, intent(in), optional :: a, b
        integer, allocatable :: tmp(:)
        if (.not. allocated(self%code)) allocate (self%code(32), self%line(32), self%col(32))
        if (self%ncode + 3 > size(self%code)) then
            allocate (tmp(2 * size(self%code)))
            tmp(1:self%ncode) = self%code(1:self%ncode); call move_alloc(tmp, self%code)
            allocate (tmp(size(self%code)))
            tmp(1:self%ncode) = self%line(1:self%ncode); call move_alloc(tmp, self%line)
            allocate (tmp(size(self%code)))
            tmp(1:self%ncode) = self%col(1:self%ncode); call move_alloc(tmp, self%col)
        end if
        call put(op)
        if (present(a)) call put(a)
        if (present(b)) call put(b)
    contains
        subroutine put(word)
            integer, intent(in) :: word
            self%ncode = self%ncode + 1
            self%code(self%ncode) = word
            self%line(self%ncode) = line
            self%col(self%ncode) = col
        end subroutine put
    end subroutine unit_emit

    !> Index of constant x in the unit's table (added if new).
    integer function unit_constant(self, x)
        class(code_unit_t), intent(inout) :: self
        real(dp), intent(in) :: x
        real(dp), allocatable :: tmp(:)
        integer :: k
        if (.not. allocated(self%consts)) allocate (self%consts(8))
        do k = 1, self%nconst
            if (same_real(self%consts(k), x)) then
                unit_constant = k
                return
            end if
        end do
        if (self%nconst == size(self%consts)) then
            allocate (tmp(2 * self%nconst))
            tmp(1:self%nconst) = self%consts(1:self%nconst)
            call move_alloc(tmp, self%consts)
        end if
        self%nconst = self%nconst + 1
        self%consts(self%nconst) = x
        unit_constant = self%nconst
    end function unit_constant

    !> Runs unit 1 of `prog` with parameter values values(slot(k)).
    !>  slot : index in values of each parameter of unit 1 (all > 0, checked by the caller)
    !>  y : out, the result;  st : out, STATUS_MODEL_ERROR located at the failing operation
    recursive subroutine run_program(prog, slot, values, y, st)
        type(program_t), intent(in) :: prog
        integer, intent(in) :: slot(:)
        real(dp), intent(in) :: values(:)
        real(dp), intent(out) :: y
        type(status_t), intent(out) :: st
        real(dp) :: stack(MAX_STACK), locals(MAX_LOCALS), r
        integer :: fr_unit(MAX_FRAMES), fr_pc(MAX_FRAMES), fr_base(MAX_FRAMES)
        integer :: sp, pc, u, base, nf, op, code, k, n
        sp = 0; pc = 1; u = 1; base = 0; nf = 0; y = 0.0_dp
        do
            op = prog%units(u)%code(pc)
            select case (op)
            case (OP_CONST)
                sp = sp + 1
                stack(sp) = prog%units(u)%consts(prog%units(u)%code(pc + 1))
            case (OP_PARAM)
                sp = sp + 1
                stack(sp) = values(slot(prog%units(u)%code(pc + 1)))
            case (OP_LOAD)
                sp = sp + 1
                stack(sp) = locals(base + prog%units(u)%code(pc + 1))
            case (OP_STORE)
                locals(base + prog%units(u)%code(pc + 1)) = stack(sp)
                sp = sp - 1
            case (OP_NEG)
                stack(sp) = -stack(sp)
            case (OP_SQUARE)
                if (abs(stack(sp)) > 1.0e154_dp) then
                    call fail(3, '** 2'); return
                end if
                stack(sp) = stack(sp) * stack(sp)
            case (OP_MUL)                     ! fast path; overflow checked before
                if (abs(stack(sp)) > 1.0_dp) then
                    if (abs(stack(sp - 1)) > huge(r) / abs(stack(sp))) then
                        call fail(3, '*'); return
                    end if
                end if
                sp = sp - 1
                stack(sp) = stack(sp) * stack(sp + 1)
            case (OP_ADD, OP_SUB)
                if (abs(stack(sp)) > HALF_HUGE .or. abs(stack(sp - 1)) > HALF_HUGE) then
                    call checked_binary(SYMBOLS(op - OP_ADD + 1), stack(sp - 1), stack(sp), &
                                        r, code)
                    if (code /= MATH_OK) then
                        call fail(code, trim(SYMBOLS(op - OP_ADD + 1))); return
                    end if
                else if (op == OP_ADD) then
                    r = stack(sp - 1) + stack(sp)
                else
                    r = stack(sp - 1) - stack(sp)
                end if
                sp = sp - 1
                stack(sp) = r
            case (OP_DIV, OP_FLOORDIV, OP_MOD)
                call checked_binary(SYMBOLS(op - OP_ADD + 1), stack(sp - 1), stack(sp), r, code)
                if (code /= MATH_OK) then
                    call fail(code, trim(SYMBOLS(op - OP_ADD + 1))); return
                end if
                sp = sp - 1
                stack(sp) = r
            case (OP_POW)
                call checked_pow(stack(sp - 1), stack(sp), r, code)
                if (code /= MATH_OK) then
                    call fail(code, '**'); return
                end if
                sp = sp - 1
                stack(sp) = r
            case (OP_LT:OP_NE)
                sp = sp - 1
                stack(sp) = merge(1.0_dp, 0.0_dp, compare(op, stack(sp), stack(sp + 1)))
            case (OP_NOT)
                stack(sp) = merge(1.0_dp, 0.0_dp, same_real(stack(sp), 0.0_dp))
            case (OP_JUMP)
                pc = prog%units(u)%code(pc + 1)
                cycle
            case (OP_JUMP_IF_FALSE)
                sp = sp - 1
                if (same_real(stack(sp + 1), 0.0_dp)) then
                    pc = prog%units(u)%code(pc + 1)
                    cycle
                end if
            case (OP_JUMP_IF_FALSE_OR_POP, OP_JUMP_IF_TRUE_OR_POP)
                if (same_real(stack(sp), 0.0_dp) .eqv. (op == OP_JUMP_IF_FALSE_OR_POP)) then
                    pc = prog%units(u)%code(pc + 1)
                    cycle
                end if
                sp = sp - 1
            case (OP_BUILTIN)
                n = prog%units(u)%code(pc + 2)
                if (n == 2 .and. (prog%units(u)%code(pc + 1) == B_MIN .or. &
                                  prog%units(u)%code(pc + 1) == B_MAX)) then
                    sp = sp - 1
                    if (prog%units(u)%code(pc + 1) == B_MIN) then
                        stack(sp) = min(stack(sp), stack(sp + 1))
                    else
                        stack(sp) = max(stack(sp), stack(sp + 1))
                    end if
                    pc = pc + 3
                    cycle
                end if
                call checked_call(prog%units(u)%code(pc + 1), stack(sp - n + 1:sp), n, r, code)
                if (code /= MATH_OK) then
                    call fail(code, builtin_name(prog%units(u)%code(pc + 1)) // '()'); return
                end if
                sp = sp - n + 1
                stack(sp) = r
            case (OP_CALL_FUNC)
                k = prog%units(u)%code(pc + 1)
                n = prog%units(u)%code(pc + 2)
                call prog%callees(k)%f%evaluate(prog%callees(k)%binding, stack(sp - n + 1:sp), &
                                                r, st)
                if (st%failed()) then
                    call locate(); return
                end if
                sp = sp - n + 1
                stack(sp) = r
            case (OP_CALL_DEF)
                k = prog%units(u)%code(pc + 1)
                n = prog%units(u)%code(pc + 2)
                if (nf == MAX_FRAMES .or. base + prog%units(u)%nlocals + &
                    prog%units(k)%nlocals > MAX_LOCALS) then
                    call fail(0, 'def calls nested too deeply'); return
                end if
                nf = nf + 1
                fr_unit(nf) = u; fr_pc(nf) = pc + 3; fr_base(nf) = base
                base = base + prog%units(u)%nlocals
                locals(base + 1:base + prog%units(k)%nlocals) = 0.0_dp
                locals(base + 1:base + n) = stack(sp - n + 1:sp)
                sp = sp - n
                u = k; pc = 1
                cycle
            case (OP_RETURN)
                if (nf == 0) then
                    y = stack(sp)
                    return
                end if
                u = fr_unit(nf); pc = fr_pc(nf); base = fr_base(nf)
                nf = nf - 1
                cycle
            case (OP_POP)
                sp = sp - 1
            case (OP_NO_RETURN)
                call fail(0, 'def ' // prog%units(u)%name // ' ended without "return"')
                return
            end select
            pc = pc + 1 + OP_OPERANDS(op)
        end do

    contains

        subroutine fail(math_code, what)
            integer, intent(in) :: math_code
            character(len=*), intent(in) :: what
            character(len=:), allocatable :: msg
            if (math_code == 0) then
                msg = what
            else
                msg = math_message(math_code, what)
            end if
            call set_error(st, STATUS_MODEL_ERROR, msg // ' while evaluating a formula')
            call locate()
        end subroutine fail

        subroutine locate()
            if (st%line /= 0) return
            st%line = prog%units(u)%line(pc)
            st%column = prog%units(u)%col(pc)
            if (allocated(prog%file)) st%file = prog%file
            if (allocated(prog%units(u)%file)) st%file = prog%units(u)%file
        end subroutine locate

    end subroutine run_program

    pure logical function compare(op, a, b)
        integer, intent(in) :: op
        real(dp), intent(in) :: a, b
        select case (op)
        case (OP_LT)
            compare = a < b
        case (OP_LE)
            compare = a <= b
        case (OP_GT)
            compare = a > b
        case (OP_GE)
            compare = a >= b
        case (OP_EQ)
            compare = same_real(a, b)
        case default
            compare = .not. same_real(a, b)
        end select
    end function compare

end module formula_program
