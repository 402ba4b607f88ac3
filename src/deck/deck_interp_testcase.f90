!> The deck evaluator (deck_interpreter), Code_Aster's test helper `CA.TestCase()`
!> (code_aster/Utilities/Tester.py, doc/deck-language.md "CA.TestCase"): its assert methods
!> are unittest's, with unittest's parameters and failure messages, but none stops the deck:
!> each writes one line to the .mess and the .resu,
!>    ` OK       assertEqual passed`  or  `NOOK       assertEqual failed : 1 != 2 - f.comm#12`
!> counted with the TEST_RESU lines (the run's verdict). printSummary() writes Code_Aster's
!> summary; `test.last_failed` says whether the last assert failed. In the check pass the
!> asserts are evaluated (a wrong argument is an error) and write nothing.
submodule(deck_interpreter) deck_interp_testcase
    use deck_concept, only: concept_t
    use deck_testcase, only: testcase_t
    use deck_suggest, only: did_you_mean
    implicit none

    !> The assert methods and their parameters (unittest's names; msg is never required).
    character(len=*), parameter :: ASSERTS(*) = [character(len=60) :: &
        'assertEqual first second msg', &
        'assertNotEqual first second msg', &
        'assertTrue expr msg', &
        'assertFalse expr msg', &
        'assertIs expr1 expr2 msg', &
        'assertIsNot expr1 expr2 msg', &
        'assertIsNone obj msg', &
        'assertIsNotNone obj msg', &
        'assertIn member container msg', &
        'assertNotIn member container msg', &
        'assertIsInstance obj cls msg', &
        'assertNotIsInstance obj cls msg', &
        'assertAlmostEqual first second places msg delta', &
        'assertNotAlmostEqual first second places msg delta', &
        'assertGreater a b msg', &
        'assertGreaterEqual a b msg', &
        'assertLess a b msg', &
        'assertLessEqual a b msg', &
        'assertSequenceEqual seq1 seq2 msg seq_type', &
        'assertListEqual list1 list2 msg', &
        'assertTupleEqual tuple1 tuple2 msg', &
        'assertDictEqual d1 d2 msg', &
        'assertMultiLineEqual first second msg', &
        'assertCountEqual first second msg', &
        'writeResult ok funcTest msg exc', &
        'printSummary', &
        'runTest']
    !> The number of required parameters of each entry of ASSERTS.
    integer, parameter :: REQUIRED(*) = [2, 2, 1, 1, 2, 2, 1, 1, 2, 2, 2, 2, 2, 2, 2, 2, 2, &
                                         2, 2, 2, 2, 2, 2, 2, 3, 0, 0]

contains

    !> CA.TestCase(methodName='runTest', silent=False): a new tester.
    module procedure new_testcase
        class(concept_t), allocatable :: made
        type(value_t), allocatable :: vals(:)
        logical, allocatable :: given(:)
        allocate (testcase_t :: made)
        call bind_parameters(ctx, id, 'TestCase', 'methodName silent', 0, args, kwargs, vals, &
                             given, st)
        if (st%failed()) return
        select type (made)
        type is (testcase_t)
            if (given(2)) made%silent = is_true(ctx, vals(2))
        end select
        block
            type(status_t) :: ost
            call ctx%concept_value(made, v, ost)
            if (ost%failed()) call fail(st, ctx, id, ost%message)
        end block
    end procedure new_testcase

    !> test.NAME(...) and test.NAME on a CA.TestCase: the asserts, printSummary, writeResult
    !> and the attribute last_failed.
    module procedure testcase_method
        type(value_t), allocatable :: p(:)
        logical, allocatable :: given(:)
        type(value_t) :: r
        character(len=:), allocatable :: message, spec
        logical :: ok, with_msg
        integer :: m
        class(concept_t), pointer :: ptr
        v%kind = VK_NONE
        ptr => obj%obj
        select type (ptr)
        type is (testcase_t)
            if (.not. called) then
                select case (name)
                case ('last_failed')
                    v = bool_value(.not. ptr%last_ok)
                case default
                    call fail(st, ctx, id, 'a CA.TestCase has no attribute ' // name // &
                        ' in parasol (it has last_failed and the methods ' // &
                        'assertEqual, assertTrue, assertAlmostEqual, ..., printSummary)')
                end select
                return
            end if
            m = assert_index(name)
            if (m == 0) then
                call fail(st, ctx, id, unknown_method(name)); return
            end if
            spec = trim(ASSERTS(m))
            spec = spec(index(spec // ' ', ' ') + 1:)
            call bind_parameters(ctx, id, name, spec, REQUIRED(m), args, kwargs, p, given, st)
            if (st%failed()) return
            if (any(args%kind == VK_UNKNOWN) .or. holds_unknown(kwargs)) return
            select case (name)
            case ('runTest')
                return
            case ('printSummary')
                call print_summary(ptr)
                return
            case ('writeResult')
                message = ''
                if (given(4)) then
                    if (p(4)%kind /= VK_NONE) message = text_of(ctx, p(4), .false.)
                end if
                call write_result(ptr, is_true(ctx, p(1)), text_of(ctx, p(2), .false.), &
                                  optional_text(3), message)
                return
            end select
            with_msg = .true.
            call judge(ok, message)
            if (st%failed()) return
            if (.not. ok .and. with_msg .and. given(msg_position())) then
                if (p(msg_position())%kind /= VK_NONE) &
                    message = message // ' : ' // text_of(ctx, p(msg_position()), .false.)
            end if
            if (ok) message = ''
            call write_result(ptr, ok, name, optional_text(msg_position()), message)
        class default
            call fail(st, ctx, id, 'not a CA.TestCase')
        end select
    contains
        !> The verdict of assert `name` on its parameters p, and unittest's message.
        subroutine judge(ok, message)
            logical, intent(out) :: ok
            character(len=:), allocatable, intent(out) :: message
            ok = .false.
            message = ''
            select case (name)
            case ('assertEqual', 'assertDictEqual', 'assertMultiLineEqual')
                call kind_check(message)
                if (len(message) > 0) return
                ok = holds('==', p(1), p(2))
                message = differ_label() // shortened_pair()
                ! unittest adds a diff on the lines after (and msg after it) for two lists,
                ! tuples, dicts or strings: the listings keep the first line
                with_msg = .not. (same_kind([VK_LIST, VK_TUPLE, VK_DICT, VK_STR]) .or. &
                                  name /= 'assertEqual')
            case ('assertSequenceEqual', 'assertListEqual', 'assertTupleEqual')
                call kind_check(message)
                if (len(message) > 0) return
                call sequence_equal(ok)
                message = differ_label() // shortened_pair()
                with_msg = .false.
            case ('assertNotEqual')
                ok = holds('!=', p(1), p(2))
                message = repr(p(1)) // ' == ' // repr(p(2))
            case ('assertTrue')
                ok = is_true(ctx, p(1))
                message = repr(p(1)) // ' is not true'
            case ('assertFalse')
                ok = .not. is_true(ctx, p(1))
                message = repr(p(1)) // ' is not false'
            case ('assertIs')
                ok = holds('is', p(1), p(2))
                message = repr(p(1)) // ' is not ' // repr(p(2))
            case ('assertIsNot')
                ok = holds('is_not', p(1), p(2))
                message = 'unexpectedly identical: ' // repr(p(1))
            case ('assertIsNone')
                ok = p(1)%kind == VK_NONE
                message = repr(p(1)) // ' is not None'
            case ('assertIsNotNone')
                ok = p(1)%kind /= VK_NONE
                message = 'unexpectedly None'
            case ('assertIn')
                ok = holds('in', p(1), p(2))
                message = repr(p(1)) // ' not found in ' // repr(p(2))
            case ('assertNotIn')
                ok = holds('not_in', p(1), p(2))
                message = repr(p(1)) // ' unexpectedly found in ' // repr(p(2))
            case ('assertIsInstance', 'assertNotIsInstance')
                call call_builtin(ctx, id, 'isinstance', p(1:2), empty_kwargs(), r, st)
                if (st%failed()) return
                ok = is_true(ctx, r) .eqv. (name == 'assertIsInstance')
                if (name == 'assertIsInstance') then
                    message = repr(p(1)) // ' is not an instance of ' // repr(p(2))
                else
                    message = repr(p(1)) // ' is an instance of ' // repr(p(2))
                end if
            case ('assertAlmostEqual', 'assertNotAlmostEqual')
                call almost_equal(ok, message)
            case ('assertGreater')
                ok = holds('>', p(1), p(2))
                message = repr(p(1)) // ' not greater than ' // repr(p(2))
            case ('assertGreaterEqual')
                ok = holds('>=', p(1), p(2))
                message = repr(p(1)) // ' not greater than or equal to ' // repr(p(2))
            case ('assertLess')
                ok = holds('<', p(1), p(2))
                message = repr(p(1)) // ' not less than ' // repr(p(2))
            case ('assertLessEqual')
                ok = holds('<=', p(1), p(2))
                message = repr(p(1)) // ' not less than or equal to ' // repr(p(2))
            case ('assertCountEqual')
                call count_equal(ok)
                message = 'Element counts were not equal:'
                with_msg = .false.
            end select
        end subroutine judge

        !> first == second, else within `places` decimal places (default 7) or `delta`.
        subroutine almost_equal(ok, message)
            logical, intent(out) :: ok
            character(len=:), allocatable, intent(out) :: message
            type(value_t) :: diff, rounded
            logical :: equal, near, by_delta
            character(len=:), allocatable :: tolerance
            integer(i8) :: places
            ok = .false.
            message = ''
            by_delta = given(5)
            if (by_delta) by_delta = p(5)%kind /= VK_NONE
            places = 7
            if (given(3)) then
                if (p(3)%kind /= VK_NONE) then
                    if (by_delta) then
                        call fail(st, ctx, id, name // '(): specify delta or places not both')
                        return
                    end if
                    if (p(3)%kind /= VK_INT) then
                        call fail(st, ctx, id, name // '(): places must be an integer, got ' // &
                                  kind_label(p(3))); return
                    end if
                    places = p(3)%i
                end if
            end if
            equal = holds('==', p(1), p(2))
            if (st%failed()) return
            if (equal) then
                near = .true.
                diff = int_value(0_i8)
            else
                if (.not. (is_number(p(1)) .and. is_number(p(2)))) then
                    call fail(st, ctx, id, name // '() compares numbers, got ' // &
                              kind_label(p(1)) // ' and ' // kind_label(p(2))); return
                end if
                call binary(ctx, id, '-', p(1), p(2), diff, st)
                if (st%failed()) return
                if (diff%kind == VK_REAL) diff%r = abs(diff%r)
                if (diff%kind == VK_INT) diff%i = abs(diff%i)
                if (by_delta) then
                    near = holds('<=', diff, p(5))
                else
                    call round_value(ctx, id, [diff, int_value(places)], rounded, st)
                    if (st%failed()) return
                    near = holds('==', rounded, int_value(0_i8))
                end if
            end if
            if (st%failed()) return
            if (by_delta) then
                tolerance = repr(p(5)) // ' delta'
            else
                tolerance = to_text(int(places, i4)) // ' places'
            end if
            if (name == 'assertAlmostEqual') then
                ok = near
                message = repr(p(1)) // ' != ' // repr(p(2)) // ' within ' // tolerance // &
                    ' (' // repr(diff) // ' difference)'
            else
                ok = .not. equal .and. .not. near
                message = repr(p(1)) // ' == ' // repr(p(2)) // ' within ' // tolerance
                if (by_delta) message = message // ' (' // repr(diff) // ' difference)'
            end if
        end subroutine almost_equal

        !> The same items, each as many times, in any order.
        subroutine count_equal(ok)
            logical, intent(out) :: ok
            type(value_t), allocatable :: a(:), b(:)
            logical, allocatable :: used(:)
            integer :: i, j
            ok = .false.
            call iterate(ctx, id, p(1), a, st)
            if (st%failed()) return
            call iterate(ctx, id, p(2), b, st)
            if (st%failed()) return
            if (size(a) /= size(b)) return
            allocate (used(size(b)))
            used = .false.
            do i = 1, size(a)
                do j = 1, size(b)
                    if (used(j)) cycle
                    if (values_equal(ctx, a(i), b(j))) exit
                end do
                if (j > size(b)) return
                used(j) = .true.
            end do
            ok = .true.
        end subroutine count_equal

        !> The type-specific asserts fail (unittest's message) on an argument of another type.
        subroutine kind_check(message)
            character(len=:), allocatable, intent(out) :: message
            integer :: want, j
            character(len=:), allocatable :: label
            character(len=6), parameter :: ORDINAL(2) = ['First ', 'Second']
            message = ''
            select case (name)
            case ('assertListEqual')
                want = VK_LIST; label = 'list'
            case ('assertTupleEqual')
                want = VK_TUPLE; label = 'tuple'
            case ('assertDictEqual')
                want = VK_DICT; label = 'dict'
            case ('assertMultiLineEqual')
                want = VK_STR; label = 'str'
            case default
                return
            end select
            do j = 1, 2
                if (p(j)%kind == want) cycle
                if (want == VK_DICT .and. p(j)%kind == VK_FACTOR) cycle
                if (want == VK_LIST .or. want == VK_TUPLE) then
                    message = trim(ORDINAL(j)) // ' sequence is not a ' // label // ': ' // &
                        repr(p(j))
                else                   ! unittest's assertIsInstance inside, with its msg
                    message = repr(p(j)) // ' is not an instance of <class ''' // label // &
                        '''> : ' // trim(ORDINAL(j)) // ' argument is not a ' // &
                        merge('dictionary', 'string    ', want == VK_DICT)
                    message = trim(message)
                end if
                with_msg = .false.
                return
            end do
        end subroutine kind_check

        !> Equal sequences, or of other types with equal items in the same order.
        subroutine sequence_equal(ok)
            logical, intent(out) :: ok
            type(value_t), allocatable :: a(:), b(:)
            integer :: j
            ok = holds('==', p(1), p(2))
            if (ok .or. st%failed()) return
            if (.not. any(p(1)%kind == [VK_LIST, VK_TUPLE, VK_STR]) .or. &
                .not. any(p(2)%kind == [VK_LIST, VK_TUPLE, VK_STR])) return
            call iterate(ctx, id, p(1), a, st)
            if (st%failed()) return
            call iterate(ctx, id, p(2), b, st)
            if (st%failed()) return
            if (size(a) /= size(b)) return
            do j = 1, size(a)
                if (.not. holds('==', a(j), b(j))) return
            end do
            ok = .true.
        end subroutine sequence_equal

        !> unittest's first words for two sequences that differ ("Lists differ: ").
        function differ_label() result(label)
            character(len=:), allocatable :: label
            label = ''
            if (name == 'assertSequenceEqual') then
                label = 'Sequences differ: '
            else if (p(1)%kind == VK_LIST .and. p(2)%kind == VK_LIST) then
                label = 'Lists differ: '
            else if (p(1)%kind == VK_TUPLE .and. p(2)%kind == VK_TUPLE) then
                label = 'Tuples differ: '
            end if
        end function differ_label

        logical function same_kind(kinds)
            integer, intent(in) :: kinds(:)
            same_kind = p(1)%kind == p(2)%kind .and. any(p(1)%kind == kinds)
        end function same_kind

        !> 'A != B' with unittest's _common_shorten_repr: reprs longer than 80 characters
        !> keep 5 of their common beginning, the part where they differ and their ends.
        function shortened_pair() result(text)
            character(len=:), allocatable :: text, a, b, prefix
            integer :: maxlen, n, common_len
            integer, parameter :: MAX_LENGTH = 80, PLACEHOLDER = 12, MIN_BEGIN = 5, &
                MIN_END = 5, MIN_COMMON = 5, MIN_DIFF = MAX_LENGTH - (MIN_BEGIN + PLACEHOLDER + &
                MIN_COMMON + PLACEHOLDER + MIN_END)
            a = repr(p(1)); b = repr(p(2))
            maxlen = max(len(a), len(b))
            if (maxlen > MAX_LENGTH) then
                n = 0
                do while (n < min(len(a), len(b)))
                    if (a(n + 1:n + 1) /= b(n + 1:n + 1)) exit
                    n = n + 1
                end do
                common_len = MAX_LENGTH - (maxlen - n + MIN_BEGIN + PLACEHOLDER)
                if (common_len > MIN_COMMON) then
                    prefix = shorten(a(1:n), MIN_BEGIN, common_len)
                    a = prefix // a(n + 1:)
                    b = prefix // b(n + 1:)
                else
                    prefix = shorten(a(1:n), MIN_BEGIN, MIN_COMMON)
                    a = prefix // shorten(a(n + 1:), MIN_DIFF, MIN_END)
                    b = prefix // shorten(b(n + 1:), MIN_DIFF, MIN_END)
                end if
            end if
            text = a // ' != ' // b
        end function shortened_pair

        function shorten(x, prefixlen, suffixlen) result(y)
            character(len=*), intent(in) :: x
            integer, intent(in) :: prefixlen, suffixlen
            character(len=:), allocatable :: y
            integer :: skip
            y = x
            skip = len(x) - prefixlen - suffixlen
            if (skip > 12) y = x(1:prefixlen) // '[' // to_text(skip) // ' chars]' // &
                x(len(x) - suffixlen + 1:)
        end function shorten

        logical function holds(op, a, b)
            character(len=*), intent(in) :: op
            type(value_t), intent(in) :: a, b
            type(value_t) :: res
            holds = .false.
            if (st%failed()) return
            call compare_pair(ctx, id, op, a, b, res, st)
            if (st%failed()) return
            holds = is_true(ctx, res)
        end function holds

        function repr(x) result(text)
            type(value_t), intent(in) :: x
            character(len=:), allocatable :: text
            text = text_of(ctx, x, .true.)
        end function repr

        !> The text of parameter k when given and not None, else ''.
        function optional_text(k) result(text)
            integer, intent(in) :: k
            character(len=:), allocatable :: text
            text = ''
            if (k < 1 .or. k > size(p)) return
            if (.not. given(k)) return
            if (p(k)%kind /= VK_NONE) text = text_of(ctx, p(k), .false.)
        end function optional_text

        !> The position of msg among the method's parameters.
        integer function msg_position()
            integer :: j, w
            character(len=:), allocatable :: rest
            msg_position = 0
            rest = spec // ' '
            w = 0
            do while (len_trim(rest) > 0)
                j = index(rest, ' ')
                w = w + 1
                if (rest(1:j - 1) == 'msg') msg_position = w
                rest = adjustl(rest(j + 1:))
                rest = trim(rest) // ' '
            end do
        end function msg_position

        !> One OK/NOOK line as Tester.writeResult writes it, counted with the test lines.
        subroutine write_result(t, passed, func, msg, exc)
            type(testcase_t), intent(inout) :: t
            logical, intent(in) :: passed
            character(len=*), intent(in) :: func, msg, exc
            character(len=:), allocatable :: line, f
            if (ctx%checking .or. t%silent) return     ! silent: not even counted (Tester.py)
            t%last_ok = passed
            if (passed) then
                t%passed = t%passed + 1
            else
                t%failure = t%failure + 1
            end if
            call ctx%count_test(passed)
            f = func
            if (len(f) < 16) f = repeat(' ', 16 - len(f)) // f
            if (passed) then
                line = ' OK  ' // f // ' passed'
                if (len(msg) > 0) line = line // ' : ' // msg
            else
                line = 'NOOK ' // f // ' failed'
                if (len(exc) > 0) line = line // ' : ' // first_line(exc)
                line = line // ' - ' // node_file(ctx, id) // '#' // &
                    to_text(int(ctx%ast%nodes(id)%line, i4))
            end if
            call ctx%write_mess(line)
            call ctx%write_resu(line)
        end subroutine write_result

        subroutine print_summary(t)
            type(testcase_t), intent(in) :: t
            call ctx%write_mess(repeat('-', 70))
            call ctx%write_mess('Ran ' // to_text(int(t%passed + t%failure, i4)) // &
                ' tests, ' // to_text(int(t%passed, i4)) // ' passed, ' // &
                to_text(int(t%failure, i4)) // ' in failure')
            call ctx%write_mess('')
            if (t%failure > 0) then
                call ctx%write_mess('NOOK')
            else
                call ctx%write_mess(' OK ')
            end if
            call ctx%write_mess('')
        end subroutine print_summary

        function unknown_method(n) result(text)
            character(len=*), intent(in) :: n
            character(len=:), allocatable :: text
            type(string_t), allocatable :: names(:)
            integer :: j
            select case (n)
            case ('assertRaises', 'assertRaisesRegex', 'assertWarns', 'assertWarnsRegex', &
                  'assertLogs')
                text = 'CA.TestCase ' // n // '(): exceptions are not part of the deck ' // &
                    'language (parasol stops at the first error)'
                return
            case ('assertRegex', 'assertNotRegex', 'assertSetEqual')
                text = 'CA.TestCase ' // n // '(): regular expressions and sets are not ' // &
                    'part of the deck language'
                return
            end select
            allocate (names(size(ASSERTS)))
            do j = 1, size(ASSERTS)
                names(j)%s = ASSERTS(j)(1:index(ASSERTS(j), ' ') - 1)
            end do
            text = 'a CA.TestCase has no method ' // n // '()' // did_you_mean(n, names)
        end function unknown_method
    end procedure testcase_method

    !> The entry of ASSERTS for method `name`, 0 if none.
    pure integer function assert_index(name)
        character(len=*), intent(in) :: name
        integer :: j
        assert_index = 0
        do j = 1, size(ASSERTS)
            if (ASSERTS(j)(1:index(ASSERTS(j), ' ') - 1) == name) assert_index = j
        end do
    end function assert_index

    !> The first line of a text (a multi-line message keeps one line in the listings).
    pure function first_line(text) result(line)
        character(len=*), intent(in) :: text
        character(len=:), allocatable :: line
        integer :: nl
        nl = index(text, achar(10))
        line = text
        if (nl > 0) line = text(1:nl - 1)
    end function first_line

    !> Python's binding of a call's arguments to the parameters named in `spec` (blank
    !> separated), the first `nreq` required: positional ones in order, then keywords.
    subroutine bind_parameters(ctx, id, what, spec, nreq, args, kwargs, vals, given, st)
        type(run_context_t), intent(in) :: ctx
        integer, intent(in) :: id, nreq
        character(len=*), intent(in) :: what, spec
        type(value_t), intent(in) :: args(:), kwargs
        type(value_t), allocatable, intent(out) :: vals(:)
        logical, allocatable, intent(out) :: given(:)
        type(status_t), intent(inout) :: st
        type(string_t), allocatable :: names(:)
        type(value_list_t) :: kw
        character(len=:), allocatable :: rest
        integer :: j, k, n
        allocate (names(0))
        rest = trim(adjustl(spec))
        do while (len(rest) > 0)
            j = index(rest // ' ', ' ')
            call append_string(names, rest(1:j - 1))
            rest = trim(adjustl(rest(min(j + 1, len(rest) + 1):)))
        end do
        n = size(names)
        allocate (vals(n), given(n))
        given = .false.
        if (size(args) > n) then
            call fail(st, ctx, id, what // '() takes at most ' // to_text(n) // &
                      ' argument(s), got ' // to_text(size(args))); return
        end if
        do j = 1, size(args)
            vals(j) = args(j)
            given(j) = .true.
        end do
        if (nitems(kwargs) > 0) then
            kw = unpack_value(kwargs)
            do k = 1, size(kw%keys)
                do j = 1, n
                    if (names(j)%s == kw%keys(k)%s) exit
                end do
                if (j > n) then
                    call fail(st, ctx, id, what // '() got an unexpected keyword argument ' // &
                              kw%keys(k)%s // did_you_mean(kw%keys(k)%s, names)); return
                end if
                if (given(j)) then
                    call fail(st, ctx, id, what // '() got multiple values for argument ' // &
                              kw%keys(k)%s); return
                end if
                vals(j) = kw%items(k)
                given(j) = .true.
            end do
        end if
        do j = 1, nreq
            if (.not. given(j)) then
                call fail(st, ctx, id, what // '() missing required argument ' // names(j)%s)
                return
            end if
        end do
    end subroutine bind_parameters

end submodule deck_interp_testcase
