!> The deck evaluator (deck_interpreter), its math: round (halves to even, as Python 3) and
!> the math functions, deck_math's (checked before they are computed: no FP trap) and fabs
!> hypot degrees radians isclose, log with a base.
submodule(deck_interpreter) deck_interp_math
    use deck_math
    use deck_format, only: format_spec_t, format_real
    implicit none

contains

    !> round(x): the nearest integer, halves to even (Python 3); round(x, n): the real
    !> nearest to x rounded to n decimals, correctly rounded (deck_format's digits).
    module procedure round_value
        real(dp) :: x0, r, scale
        integer(i8) :: n
        type(format_spec_t) :: spec
        character(len=:), allocatable :: digits, message
        integer :: ios
        logical :: to_int
        if (.not. is_number(args(1))) then
            call fail(st, ctx, id, 'round() takes a number, got ' // kind_label(args(1)))
            return
        end if
        to_int = size(args) == 1
        if (.not. to_int) to_int = args(2)%kind == VK_NONE
        if (to_int) then
            if (args(1)%kind /= VK_REAL) then
                v = int_value(args(1)%i); return
            end if
            x0 = args(1)%r
            if (.not. (abs(x0) < 9.2e18_dp)) then
                call fail(st, ctx, id, 'round() of ' // text_of(ctx, args(1), .true.) // &
                          ' is beyond the integer range'); return
            end if
            v = int_value(nint(half_even(x0), i8))
            return
        end if
        if (args(2)%kind /= VK_INT .and. args(2)%kind /= VK_BOOL) then
            call fail(st, ctx, id, 'round() takes an integer number of decimals'); return
        end if
        n = args(2)%i
        if (args(1)%kind /= VK_REAL) then              ! round(1234, -2) = 1200
            if (n >= 0) then
                v = int_value(args(1)%i); return
            end if
            if (n < -18) then
                v = int_value(0_i8); return
            end if
            r = real(args(1)%i, dp) / 10.0_dp**(-n)
            v = int_value(nint(half_even(r), i8) * 10_i8**(-n))
            return
        end if
        x0 = args(1)%r
        if (n >= 0) then
            spec%type = 'f'; spec%precision = int(min(n, 320_i8))
            call format_real(x0, spec, digits, message)
            read (digits, *, iostat=ios) r
            v = real_value(r)
        else
            if (n < -308) then
                v = real_value(0.0_dp); return
            end if
            scale = 10.0_dp**(-n)
            v = real_value(half_even(x0 / scale) * scale)
        end if
    end procedure round_value

    !> The integer nearest to y (a real), halves to the even one.
    pure real(dp) function half_even(y)
        real(dp), intent(in) :: y
        real(dp) :: t
        half_even = anint(y)
        t = y - aint(y)
        if (abs(abs(t) - 0.5_dp) < tiny(1.0_dp)) then
            half_even = aint(y)
            if (mod(half_even, 2.0_dp) > 0.5_dp .or. mod(half_even, 2.0_dp) < -0.5_dp) &
                half_even = half_even + sign(1.0_dp, y)
        end if
    end function half_even

    !> The math functions: deck_math's (checked: no FP trap) and fabs hypot degrees
    !> radians isclose, log(x, base).
    module procedure call_math
        real(dp), allocatable :: xs(:)
        real(dp) :: r, big, small, scale, tol_r, tol_a
        integer :: b, code, j
        character(len=:), allocatable :: bare
        logical :: found
        bare = name
        if (index(name, 'math.') == 1) bare = name(6:)
        if (nitems(kwargs) > 0 .and. bare /= 'isclose') then
            call only_kwargs(ctx, id, bare // '()', kwargs, '', st); return
        end if
        allocate (xs(size(args)))
        do j = 1, size(args)
            if (.not. is_number(args(j))) then
                call fail(st, ctx, id, bare // '() takes numbers, got ' // &
                          kind_label(args(j))); return
            end if
            xs(j) = as_real(args(j))
        end do
        select case (bare)
        case ('fabs')
            call arity(ctx, id, bare, args, kwargs, 1, 1, '', st)
            if (st%ok()) v = real_value(abs(xs(1)))
            return
        case ('degrees', 'radians')
            call arity(ctx, id, bare, args, kwargs, 1, 1, '', st)
            if (st%failed()) return
            scale = 180.0_dp / PI_VALUE
            if (bare == 'radians') scale = PI_VALUE / 180.0_dp
            ! huge / scale overflows when scale < 1 (radians): only degrees can overflow
            if (scale > 1.0_dp .and. abs(xs(1)) > huge(1.0_dp) / scale) then
                call fail(st, ctx, id, math_message(MATH_OVERFLOW, bare // '()')); return
            end if
            v = real_value(xs(1) * scale)
            return
        case ('hypot')
            call arity(ctx, id, bare, args, kwargs, 2, 2, '', st)
            if (st%failed()) return
            big = max(abs(xs(1)), abs(xs(2))); small = min(abs(xs(1)), abs(xs(2)))
            if (big <= 0.0_dp) then
                v = real_value(0.0_dp); return
            end if
            r = sqrt(1.0_dp + (small / big)**2)
            if (big > huge(1.0_dp) / r) then
                call fail(st, ctx, id, math_message(MATH_OVERFLOW, 'hypot()')); return
            end if
            v = real_value(big * r)
            return
        case ('isclose')
            call arity(ctx, id, bare, args, kwargs, 2, 2, 'rel_tol abs_tol', st)
            if (st%failed()) return
            tol_r = 1.0e-9_dp; tol_a = 0.0_dp
            call kwarg(kwargs, 'rel_tol', v, found)
            if (found .and. is_number(v)) tol_r = as_real(v)
            call kwarg(kwargs, 'abs_tol', v, found)
            if (found .and. is_number(v)) tol_a = as_real(v)
            if (abs(xs(1)) > huge(1.0_dp) / 2 .or. abs(xs(2)) > huge(1.0_dp) / 2) then
                v = bool_value(xs(1) >= xs(2) .and. xs(1) <= xs(2)); return
            end if
            v = bool_value(abs(xs(1) - xs(2)) <= max(tol_r * max(abs(xs(1)), &
                           abs(xs(2))), tol_a))
            return
        case ('log')
            if (size(xs) == 2) then
                call checked_call(B_LOG, xs(1:1), 1, r, code)
                if (code == MATH_OK) call checked_call(B_LOG, xs(2:2), 1, big, code)
                if (code == MATH_OK .and. abs(big) < tiny(1.0_dp)) code = MATH_ZERO_DIVISION
                if (code /= MATH_OK) then
                    call fail(st, ctx, id, math_message(code, 'log()')); return
                end if
                v = real_value(r / big)
                return
            end if
        end select
        b = builtin_id(bare)
        if (b == 0) then
            call fail(st, ctx, id, name // ' cannot be called'); return
        end if
        if (builtin_arity_of(b) > 0 .and. size(xs) /= builtin_arity_of(b)) then
            call fail(st, ctx, id, bare // '() takes ' // to_text(int(builtin_arity_of(b), &
                i4)) // ' argument(s), got ' // to_text(int(size(xs), i4)))
            return
        end if
        call checked_call(b, xs, size(xs), r, code)
        if (code /= MATH_OK) then
            call fail(st, ctx, id, math_message(code, bare // '()')); return
        end if
        select case (b)
        case (B_FLOOR, B_CEIL)
            if (abs(r) >= 9.2e18_dp) then
                call fail(st, ctx, id, bare // '() result out of the integer range'); return
            end if
            v = int_value(int(r, i8))
        case default
            v = real_value(r)
        end select
    end procedure call_math
end submodule deck_interp_math
